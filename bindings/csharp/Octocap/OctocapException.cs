using System;

namespace Octocap
{
    /// <summary>A failed octocap call: the native result code and the library's own message.</summary>
    public class OctocapException : Exception
    {
        public Result Result { get; }

        public OctocapException(Result result, string message) : base(message + " (" + result + ")") { Result = result; }

        /// <summary>Throws for an error (a negative result), with the message the library left on this thread; returns
        /// Ok and the statuses (NoPerson, Timeout), which are normal outcomes.</summary>
        internal static Result Check(Result r)
        {
            if ((int)r < 0) throw new OctocapException(r, NativeMethods.Utf8(NativeMethods.octocap_last_error()));
            return r;
        }
    }
}
