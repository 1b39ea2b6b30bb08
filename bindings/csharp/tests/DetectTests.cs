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
                cfg.Detector.SetModel("movenet-lightning");
                cfg.Detector.Threads = 1;
                using (var session = new Session(cfg, calib))
                {
                    var pixels = new byte[128 * 72 * 4];  // the sample cameras are 1280x720: a tenth of that
                    fixed (byte* p = pixels)
                    {
                        var images = new Image[calib.CameraCount];
                        for (int v = 0; v < images.Length; ++v)
                            images[v] = new Image { Pixels = (IntPtr)p, Width = 128, Height = 72, StrideBytes = 128 * 4, Format = PixelFormat.Rgba8 };
                        var e = Assert.Throws<OctocapException>(() => session.SolveImages(images, 0));
                        Assert.AreEqual(Result.NotEnoughViews, e.Result);
                        StringAssert.Contains("at least 2", e.Message);
                        images[2].StrideBytes = 3;
                        e = Assert.Throws<OctocapException>(() => session.SolveImages(images, 1));
                        Assert.AreEqual(Result.InvalidArgument, e.Result);
                        StringAssert.Contains("image 2", e.Message);
                    }
                    Assert.AreEqual(0, session.Detections(0, new Keypoint2D[64]));
                    DetectInfo info = session.DetectInfo;
                    Assert.AreEqual((uint)calib.CameraCount, info.Inferences);
                    Assert.AreEqual(Layout.Coco17, info.Layout);
                    Assert.AreEqual(17u, info.KeypointCount);
                    byte* name = info.Model;
                    Assert.AreEqual("movenet-lightning", Marshal.PtrToStringAnsi((IntPtr)name));
                }
            }
        }
    }
}
