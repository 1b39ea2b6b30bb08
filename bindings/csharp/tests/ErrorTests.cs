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
                e = Assert.Throws<OctocapException>(() => session.Solve(kps, 5, 0));  // too short for 5 views
                Assert.AreEqual(Result.InvalidArgument, e.Result);
                e = Assert.Throws<OctocapException>(() => session.GetKeypoints3D(new Joint[25]));
                Assert.AreEqual(Result.NoResult, e.Result);
                var nan = new Keypoint2D[25 * 5];
                for (int i = 0; i < nan.Length; ++i) nan[i] = new Keypoint2D(float.NaN, float.NaN, 0.9f);
                e = Assert.Throws<OctocapException>(() => session.Solve(nan, 5, 0));
                Assert.AreEqual(Result.NotEnoughViews, e.Result);
            }
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
