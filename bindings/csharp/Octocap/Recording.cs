using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>An OpenPose JSON recording: one folder per camera, one file per frame.</summary>
    public sealed class Recording : IDisposable
    {
        readonly RecordingHandle _handle;
        public int ViewCount { get; }
        public int FrameCount { get; }
        public Layout Layout { get; }

        public Recording(string directory, Layout layout = Layout.Auto)
        {
            OctocapException.Check(NativeMethods.octocap_recording_open(NativeMethods.Utf8Z(directory), layout, out _handle));
            uint v, f;
            Layout l;
            OctocapException.Check(NativeMethods.octocap_recording_view_count(_handle, out v));
            OctocapException.Check(NativeMethods.octocap_recording_frame_count(_handle, out f));
            OctocapException.Check(NativeMethods.octocap_recording_layout(_handle, out l));
            ViewCount = (int)v;
            FrameCount = (int)f;
            Layout = l;
        }

        /// <summary>Reads a frame into caller buffers; returns the keypoint count. Grow <paramref name="keypoints"/>
        /// when it throws BufferTooSmall (the exception does not say the size; <see cref="KeypointsNeeded"/> does).</summary>
        public unsafe int ReadFrame(int frame, Span<Keypoint2D> keypoints, Span<uint> peoplePerView)
        {
            if (peoplePerView.Length < ViewCount) throw new ArgumentException("peoplePerView is shorter than ViewCount");
            uint n;
            fixed (Keypoint2D* p = &MemoryMarshal.GetReference(keypoints))
            fixed (uint* ppv = &MemoryMarshal.GetReference(peoplePerView))
                OctocapException.Check(NativeMethods.octocap_recording_read_frame(_handle, (uint)frame, p, (uint)keypoints.Length,
                                                                                  out n, ppv, (uint)ViewCount));
            return (int)n;
        }

        public unsafe int KeypointsNeeded(int frame)
        {
            uint n;
            uint* ppv = stackalloc uint[ViewCount];
            OctocapException.Check(NativeMethods.octocap_recording_read_frame(_handle, (uint)frame, null, 0, out n, ppv, (uint)ViewCount));
            return (int)n;
        }

        public void Dispose() => _handle.Dispose();
    }
}
