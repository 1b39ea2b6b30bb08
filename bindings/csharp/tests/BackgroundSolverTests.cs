using System;
using System.Diagnostics;
using System.IO;
using System.Threading;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class BackgroundSolverTests
    {
        static readonly string Videos = TestEnv.Root + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/";
        static readonly string Lab = TestEnv.Root + "/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml";
        const int W = 272, H = 480, Frames = 12;

        // The real take's first frames of one view as RGBA (ffmpeg decodes; C# has no video decoder of its own).
        static byte[] Decode(int camera)
        {
            string raw = TestEnv.TempFile("cam" + camera + ".rgba");
            var p = Process.Start(new ProcessStartInfo("ffmpeg", "-loglevel error -y -i " + Videos + "cam0" + camera +
                                                       ".mp4 -frames:v " + Frames + " -vf scale=" + W + ":" + H +
                                                       " -f rawvideo -pix_fmt rgba " + raw) { UseShellExecute = false });
            p.WaitForExit();
            Assert.AreEqual(0, p.ExitCode);
            byte[] bytes = File.ReadAllBytes(raw);
            File.Delete(raw);
            Assert.AreEqual(Frames * W * H * 4, bytes.Length);
            return bytes;
        }

        /// <summary>A game loop submits the real take's pictures and never waits: the worker solves the newest,
        /// frames come out through IFrameSource with the person in them, sets the worker had no time for are
        /// counted, and a bad set is reported without stopping the worker.</summary>
        [Test]
        public void SolvesSubmittedPicturesOnItsOwnThread()
        {
            var views = new byte[4][];
            for (int c = 0; c < 4; ++c) views[c] = Decode(c + 1);
            using (var calib = Calibration.Load(Lab))
            {
                SessionConfig cfg = SessionConfig.Default;
                cfg.Layout = Layout.Coco17;
                using (var session = new Session(cfg, calib))
                {
                    DetectorConfig det = DetectorConfig.Default;
                    det.SetModel("movenet-lightning");
                    session.SetDetector(det);
                    using (var solver = new BackgroundSolver(session, 4))
                    {
                        Assert.IsNull(solver.TryGetFrame(), "nothing before the first set");
                        int withPerson = 0, submitted = 0;
                        for (int round = 0; round < 3; ++round)
                            for (int f = 0; f < Frames; ++f)
                            {
                                BackgroundSolver.ImageSet set = solver.Rent();
                                for (int c = 0; c < 4; ++c)
                                    Buffer.BlockCopy(views[c], f * W * H * 4, set.Resize(c, W, H), 0, W * H * 4);
                                set.TimestampUs = (round * Frames + f) * 16667L;
                                solver.Submit(set);  // returns at once, whatever the worker does
                                ++submitted;
                                using (Frame frame = solver.TryGetFrame())
                                    if (frame != null && frame.PersonCount > 0) ++withPerson;
                                Thread.Sleep(5);  // a game frame's other work
                            }
                        var deadline = DateTime.UtcNow.AddSeconds(30);
                        while (solver.Solved + solver.Replaced < submitted && DateTime.UtcNow < deadline) Thread.Sleep(20);
                        using (Frame frame = solver.TryGetFrame())
                            if (frame != null && frame.PersonCount > 0) ++withPerson;
                        Assert.AreEqual(submitted, solver.Solved + solver.Replaced, "every set solved or replaced");
                        // One more set once the worker is idle: solved for certain, however loaded the machine was
                        // while the loop above ran (under load the worker may have had time for one set only).
                        long solvedBefore = solver.Solved;
                        BackgroundSolver.ImageSet last = solver.Rent();
                        for (int c = 0; c < 4; ++c)
                            Buffer.BlockCopy(views[c], (Frames - 1) * W * H * 4, last.Resize(c, W, H), 0, W * H * 4);
                        last.TimestampUs = 3 * Frames * 16667L;
                        solver.Submit(last);
                        deadline = DateTime.UtcNow.AddSeconds(30);
                        while (solver.Solved == solvedBefore && DateTime.UtcNow < deadline) Thread.Sleep(20);
                        using (Frame frame = solver.TryGetFrame())
                            if (frame != null && frame.PersonCount > 0) ++withPerson;
                        Assert.GreaterOrEqual(solver.Solved, 2);
                        Assert.GreaterOrEqual(withPerson, 2);
                        Assert.IsNull(solver.LastError);

                        BackgroundSolver.ImageSet bad = solver.Rent();
                        for (int c = 0; c < 4; ++c) bad.Resize(c, 100, 100);  // not the cameras' aspect
                        long before = solver.Solved;
                        solver.Submit(bad);
                        deadline = DateTime.UtcNow.AddSeconds(30);
                        while (solver.LastError == null && DateTime.UtcNow < deadline) Thread.Sleep(20);
                        StringAssert.Contains("aspect", solver.LastError);
                        Assert.AreEqual(before, solver.Solved);
                        Assert.Throws<ArgumentException>(() => solver.Submit(null));
                    }
                }
            }
        }
    }
}
