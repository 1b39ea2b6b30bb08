// These tests keep the deprecated 0.x queries working beside frames, so they call them on purpose.
#pragma warning disable CS0618

using System;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class MotionTests
    {
        /// <summary>A BVH from C# gives the same bones in Unity's frame as in the rig's, mirrored as octocap defines
        /// (X flipped: a rig quaternion (x, y, z, w) is (x, -y, -z, w) in Unity).</summary>
        [Test]
        public void BvhPlaysBackWithUnityBones()
        {
            using (var motion = new Motion("/usr/share/assimp/models/BVH/01_01.bvh"))
            {
                Assert.AreEqual(2752, motion.FrameCount);
                Assert.AreEqual(120.0, motion.RateHz, 1e-2);  // the file says 0.008333 s per frame
                var rig = new BonePose[(int)BoneId.Count];
                var unity = new BonePose[(int)BoneId.Count];
                Assert.AreEqual((int)BoneId.Count, motion.GetBones(500, CoordFrame.Rig, rig));
                motion.GetBones(500, CoordFrame.Unity, unity);
                for (int b = 0; b < rig.Length; ++b)
                {
                    Assert.AreEqual(1u, rig[b].Valid);
                    Assert.AreEqual(rig[b].GlobalRotation.X, unity[b].GlobalRotation.X, 1e-6);
                    Assert.AreEqual(-rig[b].GlobalRotation.Y, unity[b].GlobalRotation.Y, 1e-6);
                    Assert.AreEqual(-rig[b].GlobalRotation.Z, unity[b].GlobalRotation.Z, 1e-6);
                    Assert.AreEqual(rig[b].GlobalRotation.W, unity[b].GlobalRotation.W, 1e-6);
                }
                var joints = new Joint[(int)JointId.Count];
                Assert.AreEqual((int)JointId.Count, motion.GetJoints(500, joints));
                var e = Assert.Throws<OctocapException>(() => motion.GetJoints(motion.FrameCount, joints));
                Assert.AreEqual(Result.InvalidArgument, e.Result);
            }
            var missing = Assert.Throws<OctocapException>(() => new Motion("/nonexistent.bvh"));
            Assert.AreEqual(Result.Io, missing.Result);
        }

        /// <summary>A motion's frames are the same frame type as a session's: the frame family gives exactly what the
        /// 0.x per-motion queries give, and the engine-free driver step reads them.</summary>
        [Test]
        public unsafe void MotionFramesAreFrames()
        {
            using (var motion = new Motion("/usr/share/assimp/models/BVH/01_01.bvh"))
            using (Frame frame = motion.GetFrame(700))
            {
                FrameSummary s = frame.Summary;
                Assert.AreEqual(700, s.FrameIndex);
                Assert.AreEqual(1u, s.PersonCount);
                Assert.AreEqual(1u, s.JointsInRigFrame);
                Assert.AreNotEqual(0u, s.DefinitionCounter);
                Assert.AreEqual(1u, frame.GetPerson(0).Id);
                Assert.AreEqual((uint)JointId.Count - 2, frame.GetPerson(0).JointsSolved);  // a BVH has no heels
                var a = new BonePose[(int)BoneId.Count];
                var b = new BonePose[(int)BoneId.Count];
                frame.GetBones(0, CoordFrame.Godot, a);
                motion.GetBones(700, CoordFrame.Godot, b);
                fixed (BonePose* pa = a)
                fixed (BonePose* pb = b)
                    for (int i = 0; i < a.Length * sizeof(BonePose); ++i) Assert.AreEqual(((byte*)pa)[i], ((byte*)pb)[i]);
                var source = new OneFrame(motion, 700);
                var c = new BonePose[(int)BoneId.Count];
                Assert.IsTrue(Octocap.Avatar.FrameReader.TryReadBones(source, 0, CoordFrame.Godot, c));
                Assert.AreEqual(a[(int)BoneId.RUpperArm].GlobalRotation.X, c[(int)BoneId.RUpperArm].GlobalRotation.X);
                Assert.IsFalse(Octocap.Avatar.FrameReader.TryReadBones(source, 1, CoordFrame.Godot, c), "no second person");
                Assert.Throws<ArgumentException>(() => Octocap.Avatar.FrameReader.TryReadBones(source, 0, CoordFrame.Godot, new BonePose[3]));
                Assert.Throws<ArgumentOutOfRangeException>(() => motion.GetFrame(-1));
            }
        }

        sealed class OneFrame : IFrameSource
        {
            readonly Motion _motion;
            readonly int _index;
            public OneFrame(Motion motion, int index) { _motion = motion; _index = index; }
            public Frame TryGetFrame() => _motion.GetFrame(_index);
        }
    }
}
