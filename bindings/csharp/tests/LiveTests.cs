using System;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class LiveTests
    {
        static readonly string Videos = TestEnv.Root + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/";
        static readonly string Lab = TestEnv.Root + "/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml";

        /// <summary>Four real videos as cameras: frames come out on the library's threads, read without blocking.</summary>
        [Test]
        public void FramesFromFourVideosAsCameras()
        {
            using (var calib = Calibration.Load(Lab))
            {
                SessionConfig session = SessionConfig.Default;
                session.Layout = Layout.Coco17;
                var cameras = new string[4];
                for (int c = 0; c < 4; ++c) cameras[c] = Videos + "cam0" + (c + 1) + ".mp4";
                using (var live = new Live(LiveConfig.Default, session, calib, cameras))
                {
                    DetectorConfig det = DetectorConfig.Default;
                    det.SetModel("movenet-lightning");
                    live.SetDetector(det);
                    Assert.AreEqual(Result.InvalidArgument,
                                    Assert.Throws<OctocapException>(() => live.SetLatencyOffsets(new[] { 0, 1 })).Result);
                    live.SetLatencyOffsets(new[] { 0, 0, 0, 0 });
                    string take = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "octocap-cs-take-" + Guid.NewGuid());
                    live.SetRecording(take);
                    Assert.IsNull(live.TryGetFrame(), "nothing before the start, and no waiting");
                    live.Start();
                    int withPerson = 0;
                    var bones = new BonePose[(int)BoneId.Count];
                    for (Frame f; (f = live.TakeFrame(10000)) != null;)
                        using (f)
                            if (f.PersonCount > 0)
                            {
                                ++withPerson;
                                f.GetBones(0, CoordFrame.Unity, bones);
                            }
                    Assert.GreaterOrEqual(withPerson, 1);
                    Assert.AreEqual(1u, live.Stats.Finished);
                    LiveStats last = live.Stats;
                    Assert.That(last.ViewsInSet, Is.InRange(1u, 4u), "the cameras the last set held (1.13)");
                    Assert.LessOrEqual(last.ViewsDetected, last.ViewsInSet, "detected among the set's views");
                    live.Stop();
                    Assert.AreEqual(live.Stats.FrameSets, live.Stats.SetsRecorded, "every solved set is recorded");
                    Assert.IsTrue(System.IO.File.Exists(System.IO.Path.Combine(take, "timestamps.csv")));
                    Assert.IsTrue(System.IO.File.Exists(System.IO.Path.Combine(take, "calibration.toml")));
                    System.IO.Directory.Delete(take, true);
                    for (int c = 0; c < 4; ++c)
                    {
                        CameraStatus s = live.Camera(c);
                        Assert.AreEqual(CameraState.Ended, s.State);
                        Assert.GreaterOrEqual(s.Grabbed, 95ul);
                        StringAssert.StartsWith("cam_", s.Name.ToString());
                    }
                    Assert.Throws<ArgumentOutOfRangeException>(() => live.Camera(-1));
                }
                var e = Assert.Throws<OctocapException>(() => new Live(LiveConfig.Default, session, calib, new[] { Videos + "cam01.mp4" }));
                Assert.AreEqual(Result.CameraMismatch, e.Result);
                cameras[3] = "/nonexistent.mp4";
                e = Assert.Throws<OctocapException>(() => new Live(LiveConfig.Default, session, calib, cameras));
                Assert.AreEqual(Result.Io, e.Result);
                StringAssert.Contains("/nonexistent.mp4", e.Message);
            }
        }
    }
}
