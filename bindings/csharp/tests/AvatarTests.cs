// These tests keep the deprecated 0.x queries working beside frames, so they call them on purpose.
#pragma warning disable CS0618

using System;
using NUnit.Framework;
using Octocap.Avatar;

namespace Octocap.Tests
{
    [TestFixture]
    public class AvatarTests
    {
        [Test]
        public void EveryBoneHasAnEngineName()
        {
            Assert.AreEqual((int)BoneId.Count, BoneNames.UnityHumanBodyBones.Length);
            Assert.AreEqual((int)BoneId.Count, BoneNames.GodotHumanoid.Length);
            Assert.AreEqual("Hips", BoneNames.UnityHumanBodyBones[(int)BoneId.Root]);
            Assert.AreEqual("LeftLowerArm", BoneNames.UnityHumanBodyBones[(int)BoneId.LLowerArm]);
            Assert.AreEqual("RightUpperLeg", BoneNames.GodotHumanoid[(int)BoneId.RUpperLeg]);
        }

        /// <summary>A person turned 90 degrees to their left, solved by the library, comes out in each engine's frame.</summary>
        [Test]
        public void KnownRotationMapsToTheExpectedEngineRotation()
        {
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            {
                SessionConfig cfg = SessionConfig.Default;
                cfg.Filter = Filter.None;
                cfg.Method = Method.Triangulation;
                using (var session = new Session(cfg, calib))
                {
                    // A T-posed body (rig frame: left is +X, facing +Z), turned 90 degrees about +Y, projected.
                    Quat yaw = QuatMath.FromAxisAngle(0, 1, 0, (float)(Math.PI / 2));
                    var kps = new Keypoint2D[5 * 25];
                    for (int v = 0; v < 5; ++v) ProjectTPose(calib, v, yaw, 0, kps, v * 25);
                    session.Solve(kps, 5, 0);
                    var bones = new BonePose[(int)BoneId.Count];
                    session.GetBones(CoordFrame.Rig, bones);
                    Assert.Less(QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, yaw), 0.02);
                    // Unity mirrors X: a left turn is a right turn there.
                    session.GetBones(CoordFrame.Unity, bones);
                    Assert.Less(QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, QuatMath.FromAxisAngle(0, 1, 0, (float)(-Math.PI / 2))), 0.02);
                    // Godot turns the world half a turn about Y: a yaw stays a yaw.
                    session.GetBones(CoordFrame.Godot, bones);
                    Assert.Less(QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, yaw), 0.02);
                    Assert.Less(QuatMath.Angle(bones[(int)BoneId.LLowerArm].LocalRotation, QuatMath.Identity), 0.05);
                }
            }
        }

        /// <summary>The T-posed body turned by <paramref name="turn"/> and moved <paramref name="x0"/> metres along X,
        /// projected into view <paramref name="v"/>: 25 keypoints from <paramref name="at"/>.</summary>
        internal static void ProjectTPose(Calibration calib, int v, Quat turn, float x0, Keypoint2D[] kps, int at)
        {
            float[,] tpose = TPoseBody25();
            for (int k = 0; k < 25; ++k)
            {
                float x = tpose[k, 0], y = tpose[k, 1], z = tpose[k, 2];
                QuatMath.Rotate(turn, ref x, ref y, ref z);
                double u, w;
                calib.Project(v, x + x0, y, z, out u, out w);
                kps[at + k] = new Keypoint2D((float)u, (float)w, 0.9f);
            }
        }

        static float[,] TPoseBody25()
        {
            // Nose, Neck, RShoulder, RElbow, RWrist, LShoulder, LElbow, LWrist, MidHip, RHip, RKnee, RAnkle, LHip,
            // LKnee, LAnkle, REye, LEye, REar, LEar, LBigToe, LSmallToe, LHeel, RBigToe, RSmallToe, RHeel
            return new float[,]
            {
                { 0, 1.62f, 0.1f }, { 0, 1.45f, 0 }, { -0.2f, 1.45f, 0 }, { -0.5f, 1.45f, 0 }, { -0.75f, 1.45f, 0 },
                { 0.2f, 1.45f, 0 }, { 0.5f, 1.45f, 0 }, { 0.75f, 1.45f, 0 }, { 0, 0.95f, 0 }, { -0.1f, 0.95f, 0 },
                { -0.1f, 0.5f, 0 }, { -0.1f, 0.08f, 0 }, { 0.1f, 0.95f, 0 }, { 0.1f, 0.5f, 0 }, { 0.1f, 0.08f, 0 },
                { -0.035f, 1.65f, 0.08f }, { 0.035f, 1.65f, 0.08f }, { -0.075f, 1.62f, 0 }, { 0.075f, 1.62f, 0 },
                { 0.1f, 0.02f, 0.15f }, { 0.15f, 0.02f, 0.13f }, { 0.1f, 0.02f, -0.05f }, { -0.1f, 0.02f, 0.15f },
                { -0.15f, 0.02f, 0.13f }, { -0.1f, 0.02f, -0.05f }
            };
        }

        /// <summary>A chest twisted 60 degrees against still hips, on an avatar with Chest and UpperChest: Spine,
        /// Chest and UpperChest turn 20, 40 and 60 degrees (world), on top of their own rest; the neck keeps its own
        /// rotation; without the extra bones Spine takes all of it.</summary>
        static Quat Turn(double degrees) => QuatMath.FromAxisAngle(0, 1, 0, (float)(degrees * Math.PI / 180));

        [Test]
        public void ChestTwistIsSpreadOverTheAvatarsSpineBones()
        {
            var rest = new Quat[(int)BoneId.Count];
            for (int b = 0; b < rest.Length; ++b) rest[b] = QuatMath.FromAxisAngle(1, 0, 0, 0.05f * b);
            var bones = new BonePose[(int)BoneId.Count];
            for (int b = 0; b < bones.Length; ++b) { bones[b].GlobalRotation = QuatMath.Identity; bones[b].Valid = 1; }
            Quat twist = QuatMath.FromAxisAngle(0, 1, 0, (float)(Math.PI / 3));
            bones[(int)BoneId.Torso].GlobalRotation = twist;
            bones[(int)BoneId.Head].GlobalRotation = twist;
            Quat chestRest = QuatMath.FromAxisAngle(0, 0, 1, 0.3f), upperRest = QuatMath.FromAxisAngle(0, 0, 1, -0.2f);

            var spread = new AvatarRetargeter();
            spread.CalibrateTPose(rest, null);
            spread.CalibrateSpine(new[] { chestRest, upperRest });
            Quat[] world = spread.Update(bones);
            Assert.Less(QuatMath.Angle(world[(int)BoneId.Torso], QuatMath.Multiply(Turn(20), rest[(int)BoneId.Torso])), 1e-4);
            Assert.Less(QuatMath.Angle(spread.SpineOutput[0], QuatMath.Multiply(Turn(40), chestRest)), 1e-4);
            Assert.Less(QuatMath.Angle(spread.SpineOutput[1], QuatMath.Multiply(Turn(60), upperRest)), 1e-4);
            Assert.Less(QuatMath.Angle(world[(int)BoneId.Head], QuatMath.Multiply(twist, rest[(int)BoneId.Head])), 1e-4);

            var single = new AvatarRetargeter();
            single.CalibrateTPose(rest, null);
            Assert.Less(QuatMath.Angle(single.Update(bones)[(int)BoneId.Torso], QuatMath.Multiply(twist, rest[(int)BoneId.Torso])), 1e-4);

            // The torso lost for a frame: the spine bones hold where they were against Spine.
            bones[(int)BoneId.Torso].Valid = 0;
            world = spread.Update(bones);
            Assert.Less(QuatMath.Angle(spread.SpineOutput[1], QuatMath.Multiply(Turn(60), upperRest)), 1e-4);
        }

        [Test]
        public void RetargeterAppliesRotationsOnTopOfTheAvatarsRest()
        {
            var r = new AvatarRetargeter();
            var rest = new Quat[(int)BoneId.Count];
            for (int b = 0; b < rest.Length; ++b) rest[b] = QuatMath.FromAxisAngle(1, 0, 0, 0.1f * b + 0.01f);
            var present = new bool[rest.Length];
            for (int b = 0; b < present.Length; ++b) present[b] = b != (int)BoneId.Head;
            r.CalibrateTPose(rest, present);
            var bones = new BonePose[(int)BoneId.Count];
            Quat turn = QuatMath.FromAxisAngle(0, 0, 1, 0.7f);
            for (int b = 0; b < bones.Length; ++b) { bones[b].GlobalRotation = turn; bones[b].Valid = 1; }
            bones[(int)BoneId.RLowerLeg].Valid = 0;
            Quat[] world = r.Update(bones);
            Assert.Less(QuatMath.Angle(world[(int)BoneId.Torso], QuatMath.Multiply(turn, rest[(int)BoneId.Torso])), 1e-5);
            // Unsolved (never yet): its T-pose rotation relative to its parent, so it turns with the thigh.
            Assert.Less(QuatMath.Angle(world[(int)BoneId.RLowerLeg], QuatMath.Multiply(turn, rest[(int)BoneId.RLowerLeg])), 1e-5);
            // A foot solved once, then lost: it keeps its last rotation relative to the shin, which turns on.
            bones[(int)BoneId.RLowerLeg].Valid = 1;
            r.Update(bones);
            Quat footBefore = r.Update(bones)[(int)BoneId.RFoot];
            Quat shinBefore = world[(int)BoneId.RLowerLeg];
            Quat turnMore = QuatMath.FromAxisAngle(0, 1, 0, 0.5f);
            for (int b = 0; b < bones.Length; ++b) bones[b].GlobalRotation = QuatMath.Multiply(turnMore, turn);
            bones[(int)BoneId.RFoot].Valid = 0;
            world = r.Update(bones);
            Quat expected = QuatMath.Multiply(world[(int)BoneId.RLowerLeg],
                                              QuatMath.Multiply(QuatMath.Conjugate(shinBefore), footBefore));
            Assert.Less(QuatMath.Angle(world[(int)BoneId.RFoot], expected), 1e-4);
            for (int b = 0; b < bones.Length; ++b) { bones[b].GlobalRotation = turn; bones[b].Valid = 1; }
            r.Update(bones);
            Assert.IsFalse(r.Drives(BoneId.Head));

            // With smoothing, a jump is approached over frames, never overshot.
            r.Smoothing = 0.5f;
            Quat turn2 = QuatMath.FromAxisAngle(0, 0, 1, -0.7f);
            for (int b = 0; b < bones.Length; ++b) bones[b].GlobalRotation = turn2;
            Quat target = QuatMath.Multiply(turn2, rest[(int)BoneId.Torso]);
            float last = QuatMath.Angle(r.Update(bones)[(int)BoneId.Torso], target);
            Assert.Greater(last, 0.3f);
            for (int i = 0; i < 20; ++i)
            {
                float now = QuatMath.Angle(r.Update(bones)[(int)BoneId.Torso], target);
                Assert.LessOrEqual(now, last + 1e-6f);
                last = now;
            }
            Assert.Less(last, 1e-3f);
        }
    }
}
