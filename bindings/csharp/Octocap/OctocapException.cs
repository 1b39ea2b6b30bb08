using System;

namespace Octocap
{
    /// <summary>A failed octocap call: the native result code and the library's own message.</summary>
    public class OctocapException : Exception
    {
        public Result Result { get; }

        public OctocapException(Result result, string message) : base(message + " (" + result + ")") { Result = result; }

        /// <summary>Throws for any result but Ok, with the message the library left on this thread.</summary>
        internal static void Check(Result r)
        {
            if (r != Result.Ok) throw new OctocapException(r, NativeMethods.Utf8(NativeMethods.octocap_last_error()));
        }
    }
}
