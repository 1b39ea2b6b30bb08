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
    }
}
