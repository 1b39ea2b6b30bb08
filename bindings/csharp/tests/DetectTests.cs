using System;
using System.Runtime.InteropServices;
using System.Text;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class DetectTests
    {
        /// <summary>Images from C# reach the detector: every view is run, nobody is found in black frames, and the
        /// failure comes back as the library's own error.</summary>
        [Test]
        public unsafe void SolveImagesRunsTheDetectorOnEveryView()
        {
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            {
                SessionConfig cfg = SessionConfig.Default;
                cfg.Layout = Layout.Coco17;
                using (var session = new Session(cfg, calib))
                {
                    DetectorConfig detector = DetectorConfig.Default;
                    detector.SetModel("movenet-lightning");
                    detector.Threads = 1;
                    Assert.AreEqual(0u, detector.ViewsPerFrame);
                    Assert.AreEqual(Device.Cpu, detector.Device);
                    session.SetDetector(detector);
                    var pixels = new byte[128 * 72 * 4];  // the sample cameras are 1280x720: a tenth of that
                    fixed (byte* p = pixels)
                    {
                        var images = new Image[calib.CameraCount];
                        for (int v = 0; v < images.Length; ++v)
                            images[v] = new Image { Pixels = (IntPtr)p, Width = 128, Height = 72, StrideBytes = 128 * 4, Format = PixelFormat.Rgba8 };
                        Assert.AreEqual(Result.NoPerson, session.SolveImages(images, 0));
                        images[2].StrideBytes = 3;
                        var e = Assert.Throws<OctocapException>(() => session.SolveImages(images, 1));
                        Assert.AreEqual(Result.InvalidArgument, e.Result);
                        StringAssert.Contains("image 2", e.Message);
                    }
                    Assert.AreEqual(0, session.Detections(0, new Keypoint2D[64]));
                    DetectInfo info = session.DetectInfo;
                    Assert.AreEqual((uint)calib.CameraCount, info.Inferences);
                    Assert.AreEqual(Layout.Coco17, info.Layout);
                    Assert.AreEqual(17u, info.KeypointCount);
                    Assert.AreEqual("movenet-lightning", info.Model.ToString());
                    Assert.AreEqual(0u, info.ViewsTracked);  // views_per_frame 0: every view detected
                    Assert.AreEqual(Device.Cpu, info.Device);
                }
            }
        }
    }
}
