using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>Receives skeletons streamed over DDS by a session elsewhere; queried like a local session.</summary>
    public sealed class Subscriber : IDisposable, IFrameSource
    {
        readonly SubscriberHandle _handle;

        public Subscriber(SubscriberConfig config)
        {
            OctocapException.Check(NativeMethods.octocap_subscriber_create(ref config, out _handle));
        }

        /// <summary>The next received frame, waiting up to <paramref name="timeoutMs"/>; null when none came in time.</summary>
        public Frame TakeFrame(int timeoutMs)
        {
            FrameHandle f;
            if (OctocapException.Check(NativeMethods.octocap_subscriber_take_frame(_handle, timeoutMs, out f)) == Result.Timeout)
                return null;
            return new Frame(f);
        }

        /// <summary>The next frame already received, or null (never waits).</summary>
        public Frame TryGetFrame() => TakeFrame(0);

        /// <summary>Takes the next pose, waiting up to <paramref name="timeoutMs"/>; false when none came.</summary>
        [Obsolete("A 0.x query of the last pose: take a frame with TakeFrame() instead (octocap_subscriber_take_frame)")]
        public bool Take(int timeoutMs)
        {
            Result r = NativeMethods.octocap_subscriber_take(_handle, timeoutMs);
            if (r == Result.NoResult) return false;
            OctocapException.Check(r);
            return true;
        }

        public StreamInfo StreamInfo
        {
            get { StreamInfo s; OctocapException.Check(NativeMethods.octocap_subscriber_get_stream_info(_handle, out s)); return s; }
        }

        [Obsolete("A 0.x query of the last pose: take a frame with TakeFrame() instead (octocap_subscriber_take_frame)")]
        public FrameInfo FrameInfo
        {
            get { FrameInfo f; OctocapException.Check(NativeMethods.octocap_subscriber_get_frame_info(_handle, out f)); return f; }
        }

        [Obsolete("A 0.x query of the last pose: take a frame with TakeFrame() instead (octocap_subscriber_take_frame)")]
        public unsafe int GetKeypoints3D(Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_subscriber_get_keypoints3d(_handle, p, (uint)output.Length, out n));
            return (int)n;
        }

        [Obsolete("A 0.x query of the last pose: take a frame with TakeFrame() instead (octocap_subscriber_take_frame)")]
        public unsafe int GetJoints(Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_subscriber_get_joints(_handle, p, (uint)output.Length, out n));
            return (int)n;
        }

        [Obsolete("A 0.x query of the last pose: take a frame with TakeFrame() instead (octocap_subscriber_take_frame)")]
        public unsafe int GetBones(CoordFrame frame, Span<BonePose> output)
        {
            uint n;
            fixed (BonePose* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_subscriber_get_bones(_handle, frame, p, (uint)output.Length, out n));
            return (int)n;
        }

        public void Dispose() => _handle.Dispose();
    }
}
