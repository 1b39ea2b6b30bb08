using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>A live capture (octocap_live_*): cameras in (devices, rtsp://, http://, video files, picture folders,
    /// in calibration order), frames out, on the library's threads. A game loop reads frames without ever blocking:
    /// <see cref="TryGetFrame"/> returns the newest frame (several avatars may read it), or null before the first.</summary>
    public sealed class Live : IDisposable, IFrameSource
    {
        readonly LiveHandle _handle;

        public Live(LiveConfig config, SessionConfig session, Calibration calibration, string[] cameras)
        {
            if (calibration == null) throw new ArgumentNullException(nameof(calibration));
            if (cameras == null) throw new ArgumentNullException(nameof(cameras));
            var utf8 = new IntPtr[cameras.Length];
            try
            {
                for (int i = 0; i < cameras.Length; ++i)
                {
                    if (cameras[i] == null) throw new ArgumentNullException(nameof(cameras), "camera " + i + " is null");
                    byte[] bytes = NativeMethods.Utf8Z(cameras[i]);
                    utf8[i] = Marshal.AllocHGlobal(bytes.Length);
                    Marshal.Copy(bytes, 0, utf8[i], bytes.Length);
                }
                OctocapException.Check(NativeMethods.octocap_live_create(ref config, ref session, calibration.Handle, utf8,
                                                                         (uint)cameras.Length, out _handle));
            }
            finally
            {
                foreach (IntPtr p in utf8)
                    if (p != IntPtr.Zero) Marshal.FreeHGlobal(p);
            }
        }

        public void SetDetector(DetectorConfig config) =>
            OctocapException.Check(NativeMethods.octocap_live_set_detector(_handle, ref config));

        /// <summary>Per camera (calibration order), how many microseconds late it delivers; before Start.</summary>
        public void SetLatencyOffsets(int[] offsetsUs)
        {
            if (offsetsUs == null) throw new ArgumentNullException(nameof(offsetsUs));
            OctocapException.Check(NativeMethods.octocap_live_set_latency_offsets(_handle, offsetsUs, (uint)offsetsUs.Length));
        }

        /// <summary>Records the next run into <paramref name="directory"/> (pictures, OpenPose JSON keypoints, capture
        /// times, the calibration: a take <c>octocap solve</c> reads again); null turns it off. Before Start.</summary>
        public void SetRecording(string directory) =>
            OctocapException.Check(NativeMethods.octocap_live_set_recording(_handle, directory == null ? null : NativeMethods.Utf8Z(directory)));

        /// <summary>Opens every camera (an OctocapException naming one that cannot be opened) and starts.</summary>
        public void Start() => OctocapException.Check(NativeMethods.octocap_live_start(_handle));
        public void Stop() => OctocapException.Check(NativeMethods.octocap_live_stop(_handle));

        /// <summary>The newest frame not taken yet, waiting up to <paramref name="timeoutMs"/>; null when none came.</summary>
        public Frame TakeFrame(int timeoutMs)
        {
            FrameHandle f;
            if (OctocapException.Check(NativeMethods.octocap_live_take_frame(_handle, timeoutMs, out f)) == Result.Timeout)
                return null;
            return new Frame(f);
        }

        /// <summary>The newest frame, taken or not; null before the first. Never waits: for a game loop, and for several
        /// drivers sharing one capture.</summary>
        public Frame TryGetFrame()
        {
            FrameHandle f;
            Result r = NativeMethods.octocap_live_get_frame(_handle, out f);
            if (r == Result.NoResult) return null;
            OctocapException.Check(r);
            return new Frame(f);
        }

        public LiveStats Stats
        {
            get
            {
                var s = new LiveStats { StructSize = (uint)Marshal.SizeOf(typeof(LiveStats)) };
                OctocapException.Check(NativeMethods.octocap_live_get_stats(_handle, ref s));
                return s;
            }
        }

        public CameraStatus Camera(int index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index));
            var c = new CameraStatus { StructSize = (uint)Marshal.SizeOf(typeof(CameraStatus)) };
            OctocapException.Check(NativeMethods.octocap_live_get_camera_status(_handle, (uint)index, ref c));
            return c;
        }

        public void Dispose() => _handle.Dispose();
    }
}
