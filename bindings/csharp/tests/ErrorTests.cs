// These tests keep the deprecated 0.x queries working beside frames, so they call them on purpose.
#pragma warning disable CS0618

using System;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class ErrorTests
    {
        [Test]
        public void MissingFileThrowsWithTheNativeMessage()
        {
            var e = Assert.Throws<OctocapException>(() => Calibration.Load("/nonexistent/calib.toml"));
            Assert.AreEqual(Result.Io, e.Result);
            StringAssert.Contains("/nonexistent/calib.toml", e.Message);
        }

        [Test]
        public void WrongViewCountAndShortBuffers()
        {
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            using (var session = new Session(SessionConfig.Default, calib))
            {
                var kps = new Keypoint2D[25 * 4];
                var e = Assert.Throws<OctocapException>(() => session.Solve(kps, 4, 0));
                Assert.AreEqual(Result.CameraMismatch, e.Result);
                StringAssert.Contains("5 cameras", e.Message);
                // A managed argument error is an ArgumentException, before any native call.
                Assert.Throws<ArgumentException>(() => session.Solve(kps, 5, 0));  // too short for 5 views
                e = Assert.Throws<OctocapException>(() => session.GetKeypoints3D(new Joint[25]));
                Assert.AreEqual(Result.NoResult, e.Result);
                Assert.IsNull(session.TryGetFrame(), "no frame before the first solve");
                var nan = new Keypoint2D[25 * 5];
                for (int i = 0; i < nan.Length; ++i) nan[i] = new Keypoint2D(float.NaN, float.NaN, 0.9f);
                // Nobody seen is a normal outcome: a status, not an exception, and a frame with no person.
                Assert.AreEqual(Result.NoPerson, session.Solve(nan, 5, 0));
                using (Frame frame = session.GetFrame())
                {
                    Assert.AreEqual(0, frame.PersonCount);
                    Assert.AreEqual(Result.InvalidArgument,
                                    Assert.Throws<OctocapException>(() => frame.GetJoints(0, new Joint[15])).Result);
                    Assert.Throws<ArgumentOutOfRangeException>(() => frame.GetJoints(-1, new Joint[15]));
                }
            }
        }

        /// <summary>Paths cross the boundary as UTF-8: a calibration saved under a non-ASCII name loads back.</summary>
        [Test]
        public void NonAsciiPathsRoundTrip()
        {
            string dir = TestEnv.TempFile("kalibrierung-ñ-日本");
            System.IO.Directory.CreateDirectory(dir);
            string path = dir + "/größe-カメラ.toml";
            try
            {
                using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
                {
                    calib.Save(path);
                    Assert.IsTrue(System.IO.File.Exists(path), "the file has its UTF-8 name on disk");
                    using (var back = Calibration.Load(path)) Assert.AreEqual(calib.CameraCount, back.CameraCount);
                }
            }
            finally { System.IO.Directory.Delete(dir, true); }
        }

        [Test]
        public void BadConfigIsRefused()
        {
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            {
                SessionConfig cfg = SessionConfig.Default;
                cfg.StructSize = 8;
                Assert.AreEqual(Result.StructSize, Assert.Throws<OctocapException>(() => new Session(cfg, calib)).Result);
                cfg = SessionConfig.Default;
                cfg.DeltaM = float.NaN;
                Assert.AreEqual(Result.InvalidArgument, Assert.Throws<OctocapException>(() => new Session(cfg, calib)).Result);
                cfg = SessionConfig.Default;
                cfg.Method = (Method)42;
                Assert.AreEqual(Result.InvalidArgument, Assert.Throws<OctocapException>(() => new Session(cfg, calib)).Result);
            }
        }

        [Test]
        public void LogHandlerReceivesWarnings()
        {
            int count = 0;
            Library.SetLogHandler((level, msg) => { if (level >= LogLevel.Warning) ++count; }, LogLevel.Debug);
            try
            {
                string dir = TestEnv.TempFile("rec");
                System.IO.Directory.CreateDirectory(dir + "/a");
                System.IO.Directory.CreateDirectory(dir + "/b");
                System.IO.File.WriteAllText(dir + "/a/0.json", "{\"people\": []}");
                System.IO.File.WriteAllText(dir + "/a/1.json", "{\"people\": []}");
                System.IO.File.WriteAllText(dir + "/b/0.json", "{\"people\": []}");
                using (new Recording(dir, Layout.Coco17)) { }
                System.IO.Directory.Delete(dir, true);
                Assert.GreaterOrEqual(count, 1);
            }
            finally { Library.SetLogHandler(null); }
        }
    }
}
