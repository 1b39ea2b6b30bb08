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
    /// octocap's torso is one bone from the hips to the neck; an avatar with more spine bones (Unity's and Godot's
    /// Chest and UpperChest) gets the torso's rotation against the hips spread evenly over Spine and those
    /// (<see cref="CalibrateSpine"/>), so that a twisting chest turns along the back, not at its lowest joint.
    /// </summary>
    public sealed class AvatarRetargeter
    {
        readonly Quat[] _rest = new Quat[(int)BoneId.Count];
        readonly Quat[] _output = new Quat[(int)BoneId.Count];
        readonly bool[] _has = new bool[(int)BoneId.Count];
        readonly Quat[] _local = new Quat[(int)BoneId.Count];  // last output relative to the parent's
        static readonly int[] Parents = ParentTable();
        bool _calibrated;
        Quat[] _spineRest = new Quat[0];   // T-pose world rotations of the spine bones above Spine, hips up
        Quat[] _spineOutput = new Quat[0];
        Quat[] _spineLocal = new Quat[0];  // last output relative to the torso's

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

        /// <summary>The avatar's spine bones between Spine (octocap's torso) and the neck, hips up (Unity: Chest,
        /// UpperChest; whichever it has), with their T-pose world rotations; call after <see cref="CalibrateTPose"/>.
        /// None (the default): Spine takes the whole torso rotation.</summary>
        public void CalibrateSpine(Quat[] tposeWorldRotations)
        {
            if (!_calibrated) throw new InvalidOperationException("call CalibrateTPose first");
            int n = tposeWorldRotations == null ? 0 : tposeWorldRotations.Length;
            _spineRest = new Quat[n];
            _spineOutput = new Quat[n];
            _spineLocal = new Quat[n];
            for (int i = 0; i < n; ++i)
            {
                _spineRest[i] = QuatMath.Normalize(tposeWorldRotations[i]);
                _spineOutput[i] = _spineRest[i];
                _spineLocal[i] = QuatMath.Multiply(QuatMath.Conjugate(_rest[(int)BoneId.Torso]), _spineRest[i]);
            }
        }

        /// <summary>World rotations of the spine bones given to <see cref="CalibrateSpine"/>, after each
        /// <see cref="Update"/>.</summary>
        public Quat[] SpineOutput => _spineOutput;

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
                Quat target = QuatMath.Normalize(QuatMath.Multiply(Spread(bones, b, 0), _rest[b]));
                _output[b] = Smoothing > 0 ? QuatMath.Slerp(_output[b], target, 1f - Smoothing) : target;
                _local[b] = RelativeToParent(_output, b);
            }
            UpdateSpine(bones);
            return _output;
        }

        // The rotation octocap gives bone b; for the torso with more spine bones, its share `step` (0: Spine) of the
        // turn from the hips: the hips' rotation and (step + 1) / (spine bones) of the torso's against it.
        Quat Spread(ReadOnlySpan<BonePose> bones, int b, int step)
        {
            const int torso = (int)BoneId.Torso, root = (int)BoneId.Root;
            if (b != torso || _spineRest.Length == 0 || bones[root].Valid == 0) return bones[b].GlobalRotation;
            Quat hips = bones[root].GlobalRotation;
            Quat local = QuatMath.Multiply(QuatMath.Conjugate(hips), bones[torso].GlobalRotation);
            float share = (step + 1f) / (_spineRest.Length + 1f);
            return QuatMath.Multiply(hips, QuatMath.Slerp(QuatMath.Identity, local, share));
        }

        void UpdateSpine(ReadOnlySpan<BonePose> bones)
        {
            const int torso = (int)BoneId.Torso;
            bool solved = _has[torso] && torso < bones.Length && bones[torso].Valid != 0;
            for (int i = 0; i < _spineRest.Length; ++i)
            {
                if (!solved)
                {
                    _spineOutput[i] = QuatMath.Normalize(QuatMath.Multiply(_output[torso], _spineLocal[i]));  // held
                    continue;
                }
                Quat target = QuatMath.Normalize(QuatMath.Multiply(Spread(bones, torso, i + 1), _spineRest[i]));
                _spineOutput[i] = Smoothing > 0 ? QuatMath.Slerp(_spineOutput[i], target, 1f - Smoothing) : target;
                _spineLocal[i] = QuatMath.Multiply(QuatMath.Conjugate(_output[torso]), _spineOutput[i]);
            }
        }

        public bool Drives(BoneId bone) => _has[(int)bone];
    }
}
