using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>A capture session: 2D keypoints (or images) of N views in, frames of 3D people out.
    /// One thread at a time. Solve returns <see cref="Result.Ok"/> or <see cref="Result.NoPerson"/> (a normal outcome)
    /// and throws only for errors.</summary>
    public sealed class Session : IDisposable, IFrameSource
    {
        internal readonly SessionHandle Handle;
        public int KeypointCount { get; }

        public Session(SessionConfig config, Calibration calibration)
        {
            if (calibration == null) throw new ArgumentNullException(nameof(calibration));
            SessionHandle h;
            OctocapException.Check(NativeMethods.octocap_session_create(ref config, calibration.Handle, out h));
            Handle = h;
            KeypointCount = Library.KeypointCount(config.Layout);
        }

        /// <summary>One person per view: <paramref name="keypoints"/> holds viewCount x KeypointCount keypoints.</summary>
        public unsafe Result Solve(ReadOnlySpan<Keypoint2D> keypoints, int viewCount, long timestampUs)
        {
            if (viewCount < 0) throw new ArgumentOutOfRangeException(nameof(viewCount));
            if (keypoints.Length < viewCount * KeypointCount)
                throw new ArgumentException("keypoints holds " + keypoints.Length + ", " + viewCount + " views need " +
                                            viewCount * KeypointCount, nameof(keypoints));
            fixed (Keypoint2D* p = &MemoryMarshal.GetReference(keypoints))
                return OctocapException.Check(NativeMethods.octocap_session_solve_keypoints(Handle, p, null, (uint)viewCount, timestampUs));
        }

        /// <summary>Several people per view: for each view its people, one after the other.</summary>
        public unsafe Result Solve(ReadOnlySpan<Keypoint2D> keypoints, ReadOnlySpan<uint> peoplePerView, long timestampUs)
        {
            long needed = 0;
            foreach (uint n in peoplePerView) needed += n * (long)KeypointCount;
            if (keypoints.Length < needed)
                throw new ArgumentException("keypoints holds " + keypoints.Length + ", the people need " + needed, nameof(keypoints));
            fixed (Keypoint2D* p = &MemoryMarshal.GetReference(keypoints))
            fixed (uint* ppv = &MemoryMarshal.GetReference(peoplePerView))
                return OctocapException.Check(NativeMethods.octocap_session_solve_keypoints(Handle, p, ppv, (uint)peoplePerView.Length, timestampUs));
        }

        /// <summary>The detector SolveImages uses (loaded now; without this call the default one is loaded on the
        /// first SolveImages).</summary>
        public void SetDetector(DetectorConfig config) =>
            OctocapException.Check(NativeMethods.octocap_session_set_detector(Handle, ref config));

        /// <summary>The last solved frame (dispose it). Throws NoResult before the first solve.</summary>
        public Frame GetFrame()
        {
            FrameHandle f;
            OctocapException.Check(NativeMethods.octocap_session_get_frame(Handle, out f));
            return new Frame(f);
        }

        /// <summary>The last solved frame, or null before the first solve.</summary>
        public Frame TryGetFrame()
        {
            FrameHandle f;
            Result r = NativeMethods.octocap_session_get_frame(Handle, out f);
            if (r == Result.NoResult) return null;
            OctocapException.Check(r);
            return new Frame(f);
        }

        /// <summary>Solves one frame from camera images (calibration order): the detector, then the 3D solve.
        /// Pixels must stay pinned for the call (e.g. Unity's NativeArray, or a fixed byte[]).</summary>
        public unsafe Result SolveImages(ReadOnlySpan<Image> images, long timestampUs)
        {
            fixed (Image* p = &MemoryMarshal.GetReference(images))
                return OctocapException.Check(NativeMethods.octocap_session_solve_images(Handle, p, (uint)images.Length, timestampUs));
        }

        /// <summary>The 2D keypoints the detector kept in <paramref name="view"/> last frame (people one after the
        /// other, KeypointCount each); returns how many keypoints were written.</summary>
        public unsafe int Detections(int view, Span<Keypoint2D> output)
        {
            uint count;
            fixed (Keypoint2D* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_session_detections(Handle, (uint)view, p, (uint)output.Length, out count));
            return (int)count;
        }

        /// <summary>Timings and model of the last detection.</summary>
        public DetectInfo DetectInfo
        {
            get
            {
                var info = new DetectInfo { StructSize = (uint)Marshal.SizeOf(typeof(DetectInfo)) };
                OctocapException.Check(NativeMethods.octocap_session_detect_info(Handle, ref info));
                return info;
            }
        }

        public void Reset() => OctocapException.Check(NativeMethods.octocap_session_reset(Handle));

        /// <summary>Blocks until every published frame has been handed to DDS.</summary>
        public void FlushStream() => OctocapException.Check(NativeMethods.octocap_session_flush_stream(Handle));

        /// <summary>Subscribers matched to this session's stream.</summary>
        public int StreamSubscribers
        {
            get { uint n; OctocapException.Check(NativeMethods.octocap_session_stream_subscribers(Handle, out n)); return (int)n; }
        }

        public Method Method
        {
            get { Method m; OctocapException.Check(NativeMethods.octocap_session_method(Handle, out m)); return m; }
        }

        public UpAxis UpAxis
        {
            get { UpAxis u; OctocapException.Check(NativeMethods.octocap_session_up_axis(Handle, out u)); return u; }
        }

        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public FrameInfo FrameInfo
        {
            get { FrameInfo f; OctocapException.Check(NativeMethods.octocap_session_get_frame_info(Handle, out f)); return f; }
        }

        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public uint DefinitionCounter
        {
            get { uint c; OctocapException.Check(NativeMethods.octocap_session_definition_counter(Handle, out c)); return c; }
        }

        /// <summary>Fills <paramref name="output"/> with the layout keypoints in 3D; returns how many.</summary>
        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public unsafe int GetKeypoints3D(Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_session_get_keypoints3d(Handle, p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>Fills <paramref name="output"/> with the 15 skeleton joints; returns how many.</summary>
        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public unsafe int GetJoints(Span<Joint> output)
        {
            uint n;
            fixed (Joint* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_session_get_joints(Handle, p, (uint)output.Length, out n));
            return (int)n;
        }

        /// <summary>Fills <paramref name="output"/> with the bone poses in <paramref name="frame"/>; returns how many.</summary>
        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public unsafe int GetBones(CoordFrame frame, Span<BonePose> output)
        {
            uint n;
            fixed (BonePose* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_session_get_bones(Handle, frame, p, (uint)output.Length, out n));
            return (int)n;
        }

        [Obsolete("A 0.x query of the last solve: read GetFrame() instead (octocap_session_get_frame)")]
        public unsafe int GetSelectedPeople(Span<int> output)
        {
            uint n;
            fixed (int* p = &MemoryMarshal.GetReference(output))
                OctocapException.Check(NativeMethods.octocap_session_get_selected_people(Handle, p, (uint)output.Length, out n));
            return (int)n;
        }

        public void Dispose() => Handle.Dispose();
    }
}
