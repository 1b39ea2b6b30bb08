using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>Anything that hands out solved frames: a <see cref="Session"/> or a <see cref="Live"/> capture (their
    /// newest frame: several drivers may share one), a <see cref="Subscriber"/> (the next received frame: it is taken,
    /// so give each driver its own subscriber). Engine drivers read any of them the same way.</summary>
    public interface IFrameSource
    {
        /// <summary>A new frame, or null when there is none (nothing solved yet, nothing arrived). The caller
        /// disposes it.</summary>
        Frame TryGetFrame();
    }

    /// <summary>One solved frame (octocap_frame_t): immutable, readable from any thread, valid until disposed
    /// whatever happens to its source. People are indexed 0 .. PersonCount - 1; each has a stable Id.</summary>
    public sealed class Frame : IDisposable
    {
        readonly FrameHandle _handle;

        internal Frame(FrameHandle handle) { _handle = handle; }

        public FrameSummary Summary
        {
            get
            {
                var s = new FrameSummary { StructSize = (uint)Marshal.SizeOf(typeof(FrameSummary)) };
                OctocapException.Check(NativeMethods.octocap_frame_get_summary(_handle, ref s));
                return s;
            }
        }

        public int PersonCount => (int)Summary.PersonCount;

        public Person GetPerson(int person)
        {
            var p = new Person { StructSize = (uint)Marshal.SizeOf(typeof(Person)) };
            OctocapException.Check(NativeMethods.octocap_frame_get_person(_handle, Index(person), ref p));
            return p;
        }

        /// <summary>The layout keypoints of <paramref name="person"/> in 3D; returns how many were written.</summary>
        public unsafe int GetKeypoints3D(int person, Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_frame_get_keypoints3d(_handle, Index(person), p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>The skeleton joints (JointId) of <paramref name="person"/>; returns how many were written.</summary>
        public unsafe int GetJoints(int person, Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_frame_get_joints(_handle, Index(person), p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>The bone poses of <paramref name="person"/> in <paramref name="frame"/>; returns how many.</summary>
        public unsafe int GetBones(int person, CoordFrame frame, Span<BonePose> output)
        {
            uint n;
            fixed (BonePose* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_frame_get_bones(_handle, Index(person), frame, p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>For each view, which 2D person became <paramref name="person"/> (-1: none).</summary>
        public unsafe int GetPersonViews(int person, Span<int> output)
        {
            uint n;
            fixed (int* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_frame_get_person_views(_handle, Index(person), p, (uint)output.Length, out n));
            return (int)n;
        }

        static uint Index(int person)
        {
            if (person < 0) throw new ArgumentOutOfRangeException(nameof(person), "person index must be >= 0");
            return (uint)person;
        }

        public void Dispose() => _handle.Dispose();
    }
}
