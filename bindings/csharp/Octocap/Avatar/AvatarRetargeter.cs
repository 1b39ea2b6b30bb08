using System;

namespace Octocap.Avatar
{
    /// <summary>
    /// Turns octocap bone rotations into world rotations for an avatar's bones, engine-free.
    /// octocap's global rotation of a bone is "from the T-pose". An avatar's bone has its own world rotation when
    /// the avatar stands in a T-pose (its rest); "T-pose calibrate" records those, and then
    /// target world rotation = octocap global rotation (engine frame) x the bone's T-pose world rotation.
    /// Optional smoothing blends each frame toward the target. A bone octocap could not solve keeps its last rotation
    /// relative to its parent (its T-pose one if it was never solved: the feet of a layout without feet), so it
    /// follows the body instead of snapping to the T-pose or staying put in the world.
    /// </summary>
    public sealed class AvatarRetargeter
    {
        readonly Quat[] _rest = new Quat[(int)BoneId.Count];
        readonly Quat[] _output = new Quat[(int)BoneId.Count];
        readonly bool[] _has = new bool[(int)BoneId.Count];
        readonly Quat[] _local = new Quat[(int)BoneId.Count];  // last output relative to the parent's
        static readonly int[] Parents = ParentTable();
        bool _calibrated;

        static int[] ParentTable()
        {
            var parents = new int[(int)BoneId.Count];
            for (int b = 0; b < parents.Length; ++b) parents[b] = Library.GetBoneInfo((BoneId)b).ParentBone;
            return parents;
        }

        Quat RelativeToParent(Quat[] rotations, int b) =>
            Parents[b] >= 0 ? QuatMath.Multiply(QuatMath.Conjugate(rotations[Parents[b]]), rotations[b]) : rotations[b];

        /// <summary>0 = follow exactly, towards 1 = ever smoother (and later).</summary>
        public float Smoothing { get; set; }

        public bool IsCalibrated => _calibrated;

        /// <summary>Records the avatar's world rotations in its T-pose, indexed by <see cref="BoneId"/>;
        /// a bone the avatar does not have is marked with <paramref name="present"/> false.</summary>
        public void CalibrateTPose(Quat[] tposeWorldRotations, bool[] present)
        {
            if (tposeWorldRotations == null || tposeWorldRotations.Length < (int)BoneId.Count)
                throw new ArgumentException("one rotation per octocap bone is needed");
            for (int b = 0; b < (int)BoneId.Count; ++b)
            {
                _rest[b] = QuatMath.Normalize(tposeWorldRotations[b]);
                _has[b] = present == null || present[b];
                _output[b] = _rest[b];
            }
            for (int b = 0; b < (int)BoneId.Count; ++b) _local[b] = RelativeToParent(_rest, b);
            _calibrated = true;
        }

        /// <summary>World rotation per avatar bone for this frame. <paramref name="bones"/> must be in the
        /// engine's frame (Session.GetBones with CoordFrame.Unity or Godot).</summary>
        public Quat[] Update(ReadOnlySpan<BonePose> bones)
        {
            if (!_calibrated) throw new InvalidOperationException("call CalibrateTPose first");
            // Parents come before children in BoneId order: a held bone rides on its parent's new rotation.
            for (int b = 0; b < (int)BoneId.Count; ++b)
            {
                if (!_has[b]) continue;
                if (b >= bones.Length || bones[b].Valid == 0)
                {
                    int p = Parents[b];
                    if (p >= 0 && _has[p]) _output[b] = QuatMath.Normalize(QuatMath.Multiply(_output[p], _local[b]));
                    continue;
                }
                Quat target = QuatMath.Normalize(QuatMath.Multiply(bones[b].GlobalRotation, _rest[b]));
                _output[b] = Smoothing > 0 ? QuatMath.Slerp(_output[b], target, 1f - Smoothing) : target;
                _local[b] = RelativeToParent(_output, b);
            }
            return _output;
        }

        public bool Drives(BoneId bone) => _has[(int)bone];
    }
}
