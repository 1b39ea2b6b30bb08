// These tests keep the deprecated 0.x queries working beside frames, so they call them on purpose.
#pragma warning disable CS0618

using System;
using System.IO;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class SolveTests
    {
        /// <summary>The sample recording solved frame by frame from C# gives the C program's bytes exactly.</summary>
        [Test]
        public unsafe void SampleSolvesBitIdenticalToC()
        {
            string bin = TestEnv.TempFile("c.bin");
            try
            {
                TestEnv.RunDump("solve " + TestEnv.Sample + "/calibration.toml " + TestEnv.Sample + "/keypoints " + bin);
                byte[] expected = File.ReadAllBytes(bin);
                using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
                using (var rec = new Recording(TestEnv.Sample + "/keypoints"))
                {
                    SessionConfig cfg = SessionConfig.Default;
                    cfg.Layout = rec.Layout;
                    using (var session = new Session(cfg, calib))
                    {
                        var kps = new Keypoint2D[64 * 64];
                        var people = new uint[rec.ViewCount];
                        var joints = new Joint[64];
                        var bones = new BonePose[(int)BoneId.Count];
                        var actual = new MemoryStream();
                        for (int f = 0; f < rec.FrameCount; ++f)
                        {
                            rec.ReadFrame(f, kps, people);
                            session.Solve(kps, people, f * 33333L);
                            int n = session.GetKeypoints3D(joints);
                            Write(actual, joints, n);
                            int b = session.GetBones(CoordFrame.Rig, bones);
                            Write(actual, bones, b);
                        }
                        Assert.AreEqual(90, rec.FrameCount);
                        CollectionAssert.AreEqual(expected, actual.ToArray());
                        Assert.Greater(session.FrameInfo.KeypointsSolved, 20u);
                    }
                }
            }
            finally { File.Delete(bin); }
        }

        static void Write<T>(Stream s, T[] items, int count) where T : struct
        {
            int size = Marshal.SizeOf(typeof(T));
            var buf = new byte[size * count];
            GCHandle h = GCHandle.Alloc(items, GCHandleType.Pinned);
            try { Marshal.Copy(h.AddrOfPinnedObject(), buf, 0, buf.Length); }
            finally { h.Free(); }
            s.Write(buf, 0, buf.Length);
        }

        [Test]
        public void CalibrationRoundTripsThroughSave()
        {
            string path = TestEnv.TempFile("calib.toml");
            try
            {
                using (var a = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
                {
                    a.Save(path);
                    using (var b = Calibration.Load(path))
                    {
                        Assert.AreEqual(a.CameraCount, b.CameraCount);
                        double u1, v1, u2, v2;
                        a.Project(2, 0.1, 1.2, -0.3, out u1, out v1);
                        b.Project(2, 0.1, 1.2, -0.3, out u2, out v2);
                        Assert.AreEqual(u1, u2, 1e-6);
                        Assert.AreEqual(v1, v2, 1e-6);
                    }
                }
            }
            finally { File.Delete(path); }
        }

        [Test]
        public void LibraryFacts()
        {
            Library.CheckVersion();
            StringAssert.Contains(".", Library.Version);
            Assert.GreaterOrEqual(Library.VersionNumber, Library.BindingsVersionNumber);
            Assert.AreEqual(Library.BindingsVersionNumber / 10000, Library.VersionNumber / 10000);
            Assert.AreEqual(25, Library.KeypointCount(Layout.Body25B));
            Assert.AreEqual("Head", Library.KeypointName(Layout.Body25B, 18));
            Assert.AreEqual("l_lower_arm", Library.BoneName(BoneId.LLowerArm));
            Assert.AreEqual((int)BoneId.LUpperArm, Library.GetBoneInfo(BoneId.LLowerArm).ParentBone);
        }
    }
}
