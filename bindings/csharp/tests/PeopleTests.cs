using System;
using NUnit.Framework;
using Octocap.Avatar;

namespace Octocap.Tests
{
    [TestFixture]
    public class PeopleTests
    {
        [Test]
        public void SlotsKeepTheirPersonWhenAnotherLeaves()
        {
            var slots = new PersonSlots();
            slots.Update(new uint[] { 2, 1 });
            Assert.AreEqual(1u, slots.IdOf(0));  // arriving together: in id order
            Assert.AreEqual(2u, slots.IdOf(1));
            slots.Update(new uint[] { 2 });
            Assert.AreEqual(0u, slots.IdOf(0));  // gone: the slot is free, the other keeps its person
            Assert.AreEqual(2u, slots.IdOf(1));
            slots.Update(new uint[] { 3, 2, 4 });
            Assert.AreEqual(3u, slots.IdOf(0));  // newcomers take the lowest free slots
            Assert.AreEqual(2u, slots.IdOf(1));
            Assert.AreEqual(4u, slots.IdOf(2));
            Assert.AreEqual(0u, slots.IdOf(7));
            Assert.AreEqual(0u, slots.IdOf(-1));
        }

        /// <summary>Two people solved by the library (known bodies, one turned a quarter to the left) drive two
        /// avatars by slot; when the turned one walks off, the other avatar keeps its person (an index would now
        /// point at someone else) and the free slot reads nobody.</summary>
        [Test]
        public void TwoPeopleDriveTwoAvatarsBySlot()
        {
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            {
                SessionConfig cfg = SessionConfig.Default;
                cfg.Filter = Filter.None;
                cfg.Method = Method.Triangulation;
                cfg.MaxPeople = 2;
                using (var session = new Session(cfg, calib))
                {
                    Quat turned = QuatMath.FromAxisAngle(0, 1, 0, (float)(Math.PI / 2));
                    var bones = new BonePose[(int)BoneId.Count];
                    int turnedSlot = -1;
                    for (int f = 0; f < 6; ++f)
                    {
                        bool both = f < 3;
                        var kps = new Keypoint2D[5 * 25 * (both ? 2 : 1)];
                        var perView = new uint[5];
                        for (int v = 0; v < 5; ++v)
                        {
                            int at = v * 25 * (both ? 2 : 1);
                            if (both) { AvatarTests.ProjectTPose(calib, v, turned, -0.9f, kps, at); at += 25; }
                            AvatarTests.ProjectTPose(calib, v, QuatMath.Identity, 0.9f, kps, at);
                            perView[v] = both ? 2u : 1u;
                        }
                        Assert.AreEqual(Result.Ok, session.Solve(kps, perView, f * 33333L));
                        using (Frame frame = session.GetFrame())
                            Assert.AreEqual(both ? 2 : 1, frame.PersonCount);
                        for (int slot = 0; slot < 2; ++slot)
                        {
                            bool read = FrameReader.TryReadBones(session, BindPersonBy.Slot, slot, CoordFrame.Rig, bones);
                            if (!both && slot == turnedSlot) { Assert.IsFalse(read, "the turned person left"); continue; }
                            Assert.IsTrue(read, "slot " + slot + ", frame " + f);
                            bool isTurned = QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, turned) < 0.05;
                            if (!isTurned) Assert.Less(QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, QuatMath.Identity), 0.05);
                            if (f == 0 && isTurned) turnedSlot = slot;
                            Assert.AreEqual(slot == turnedSlot, isTurned, "slot " + slot + " kept its person, frame " + f);
                        }
                        Assert.GreaterOrEqual(turnedSlot, 0);
                    }
                    // By id: the person still there.
                    using (Frame frame = session.GetFrame())
                    {
                        uint id = frame.GetPerson(0).Id;
                        Assert.IsTrue(FrameReader.TryReadBones(session, BindPersonBy.Id, (int)id, CoordFrame.Rig, bones));
                        Assert.Less(QuatMath.Angle(bones[(int)BoneId.Root].GlobalRotation, QuatMath.Identity), 0.05);
                        Assert.IsFalse(FrameReader.TryReadBones(session, BindPersonBy.Id, (int)id + 100, CoordFrame.Rig, bones));
                    }
                }
            }
        }
    }
}
