// SafeHandles: the runtime guarantees one destroy per handle, also when a finalizer runs it.
using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    public sealed class CalibrationHandle : SafeHandle
    {
        public CalibrationHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_calibration_destroy(handle); return true; }
    }

    public sealed class SessionHandle : SafeHandle
    {
        public SessionHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_session_destroy(handle); return true; }
    }

    public sealed class RecordingHandle : SafeHandle
    {
        public RecordingHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_recording_destroy(handle); return true; }
    }

    public sealed class MotionHandle : SafeHandle
    {
        public MotionHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_motion_destroy(handle); return true; }
    }

    public sealed class FrameHandle : SafeHandle
    {
        public FrameHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_frame_release(handle); return true; }
    }

    public sealed class LiveHandle : SafeHandle
    {
        public LiveHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_live_destroy(handle); return true; }
    }

    public sealed class SubscriberHandle : SafeHandle
    {
        public SubscriberHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        protected override bool ReleaseHandle() { NativeMethods.octocap_subscriber_destroy(handle); return true; }
    }
}
