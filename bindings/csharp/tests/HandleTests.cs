using System;
using System.Diagnostics;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class HandleTests
    {
        static long ResidentBytes()
        {
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();
            // VmRSS from /proc: what the process really holds, native heap included.
            foreach (string line in System.IO.File.ReadAllLines("/proc/self/status"))
                if (line.StartsWith("VmRSS:")) return long.Parse(line.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries)[1]) * 1024;
            return 0;
        }

        [Test]
        public void TenThousandCreateDestroyCyclesDoNotLeak()
        {
            string path = TestEnv.Sample + "/calibration.toml";
            for (int i = 0; i < 500; ++i) using (var c = Calibration.Load(path)) { }  // warm up allocators
            long before = ResidentBytes();
            for (int i = 0; i < 10000; ++i)
            {
                using (var c = Calibration.Load(path))
                using (var s = new Session(SessionConfig.Default, c)) { }
            }
            long growth = ResidentBytes() - before;
            // A session holds kilobytes; 10,000 leaked ones would be tens of megabytes.
            Assert.Less(growth, 8L * 1024 * 1024, "resident memory grew by " + growth + " bytes");
        }

        [Test]
        public void DisposeTwiceIsHarmlessAndUseAfterDisposeThrows()
        {
            var c = Calibration.Load(TestEnv.Sample + "/calibration.toml");
            c.Dispose();
            c.Dispose();
            Assert.Throws<ObjectDisposedException>(() => { int n = c.CameraCount; });
        }

        [Test]
        public void FinalizerReleasesForgottenHandles()
        {
            for (int i = 0; i < 1000; ++i) Calibration.Load(TestEnv.Sample + "/calibration.toml");  // never disposed
            GC.Collect();
            GC.WaitForPendingFinalizers();
            using (var c = Calibration.Load(TestEnv.Sample + "/calibration.toml")) Assert.AreEqual(5, c.CameraCount);
        }
    }
}
