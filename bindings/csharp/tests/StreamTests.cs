// These tests keep the deprecated 0.x queries working beside frames, so they call them on purpose.
#pragma warning disable CS0618

using System;
using System.Runtime.InteropServices;
using System.Threading;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class StreamTests
    {
        static unsafe void SetTopic(byte* dst, string name)
        {
            for (int i = 0; i < name.Length; ++i) dst[i] = (byte)name[i];
            dst[name.Length] = 0;
        }

        /// <summary>A session publishing over DDS (loopback) and a C# subscriber reading it give the same bytes.</summary>
        [Test]
        public unsafe void SubscriberReceivesWhatTheSessionSolved()
        {
            uint domain = (uint)(1 + System.Diagnostics.Process.GetCurrentProcess().Id % 200);
            using (var calib = Calibration.Load(TestEnv.Sample + "/calibration.toml"))
            using (var rec = new Recording(TestEnv.Sample + "/keypoints"))
            {
                SubscriberConfig sc = SubscriberConfig.Default;
                sc.DomainId = domain;
                sc.Qos = StreamQos.Record;
                SetTopic(sc.Topic, "csharp_stream");
                SessionConfig cfg = SessionConfig.Default;
                cfg.Layout = rec.Layout;
                cfg.StreamEnable = 1;
                cfg.StreamDomainId = domain;
                cfg.StreamQos = StreamQos.Record;
                SetTopic(cfg.StreamTopic, "csharp_stream");
                using (var sub = new Subscriber(sc))
                using (var session = new Session(cfg, calib))
                {
                    for (int i = 0; i < 500 && session.StreamSubscribers == 0; ++i) Thread.Sleep(10);
                    Assert.AreEqual(1, session.StreamSubscribers);
                    var kps = new Keypoint2D[4096];
                    var people = new uint[rec.ViewCount];
                    var mine = new Joint[25];
                    var theirs = new Joint[25];
                    for (int f = 0; f < 30; ++f)
                    {
                        rec.ReadFrame(f, kps, people);
                        session.Solve(kps, people, f * 33333L);
                        session.FlushStream();
                        using (Frame local = session.GetFrame())
                        using (Frame received = sub.TakeFrame(5000))
                        {
                            Assert.IsNotNull(received, "frame " + f + " did not arrive");
                            Assert.AreEqual(f, received.Summary.FrameIndex);
                            Assert.AreEqual(1, received.PersonCount);
                            Assert.AreEqual(local.GetPerson(0).KeypointsSolved, received.GetPerson(0).KeypointsSolved);
                            // The same frame read from either source, through the one frame family, is the same bytes;
                            // so is the session's deprecated 0.x query.
                            local.GetKeypoints3D(0, mine);
                            received.GetKeypoints3D(0, theirs);
                            var old = new Joint[25];
                            session.GetKeypoints3D(old);
                            fixed (Joint* a = mine)
                            fixed (Joint* b = theirs)
                            fixed (Joint* c = old)
                                for (int i = 0; i < 25 * Marshal.SizeOf(typeof(Joint)); ++i)
                                {
                                    Assert.AreEqual(((byte*)a)[i], ((byte*)b)[i]);
                                    Assert.AreEqual(((byte*)a)[i], ((byte*)c)[i]);
                                }
                        }
                    }
                    Assert.IsNull(sub.TakeFrame(50), "nothing more was sent: a timeout is null, not an exception");
                    Assert.AreEqual(30ul, sub.StreamInfo.FramesReceived);
                    Assert.AreEqual(0ul, sub.StreamInfo.FramesLost);
                    Assert.AreEqual(Layout.Body25, sub.StreamInfo.Layout);
                }
            }
        }
    }
}
