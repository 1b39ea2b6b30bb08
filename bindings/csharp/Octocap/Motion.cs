using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>A motion file played back as octocap's skeleton (octocap_motion_*): a TRC or CSV from
    /// <c>octocap solve</c>, Pose2Sim's TRC, or a BVH. Drives an avatar from a file as a live session would.</summary>
    public sealed class Motion : IDisposable
    {
        readonly MotionHandle _handle;
        public int FrameCount { get; }
        public double RateHz { get; }

        public Motion(string path)
        {
            OctocapException.Check(NativeMethods.octocap_motion_open(NativeMethods.Utf8Z(path), out _handle));
            uint frames;
            double rate;
            OctocapException.Check(NativeMethods.octocap_motion_info(_handle, out frames, out rate));
            FrameCount = (int)frames;
            RateHz = rate;
        }

        /// <summary>Frame <paramref name="index"/> (dispose it): one person when the file has joints there, rig frame.</summary>
        public Frame GetFrame(int index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index));
            FrameHandle f;
            OctocapException.Check(NativeMethods.octocap_motion_get_frame(_handle, (uint)index, out f));
            return new Frame(f);
        }

        /// <summary>The skeleton joints (JointId) of a frame, rig frame (Y up, metres); returns how many were written.</summary>
        [Obsolete("A 0.x query: read GetFrame(index) instead (octocap_motion_get_frame)")]
        public unsafe int GetJoints(int frame, Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_motion_joints(_handle, (uint)frame, p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>The bone poses of a frame in the requested coordinate frame (Unity, Godot or the rig's).</summary>
        [Obsolete("A 0.x query: read GetFrame(index) instead (octocap_motion_get_frame)")]
        public unsafe int GetBones(int frame, CoordFrame coordFrame, Span<BonePose> output)
        {
            uint n;
            fixed (BonePose* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_motion_bones(_handle, (uint)frame, coordFrame, p, (uint)output.Length, out n));
            return (int)n;
        }

        public void Dispose() => _handle.Dispose();
    }
}
