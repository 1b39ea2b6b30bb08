using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using System.Text;
using NUnit.Framework;

namespace Octocap.Tests
{
    /// <summary>Every mirrored struct has the C compiler's size and field offsets, so the two cannot drift.</summary>
    [TestFixture]
    public class StructLayoutTests
    {
        static readonly Dictionary<string, Type> Mirrors = new Dictionary<string, Type>
        {
            { "octocap_keypoint2d_t", typeof(Keypoint2D) }, { "octocap_joint_t", typeof(Joint) },
            { "octocap_quat_t", typeof(Quat) }, { "octocap_bone_pose_t", typeof(BonePose) },
            { "octocap_frame_info_t", typeof(FrameInfo) }, { "octocap_bone_info_t", typeof(BoneInfo) },
            { "octocap_camera_t", typeof(CameraData) }, { "octocap_session_config_t", typeof(SessionConfig) },
            { "octocap_subscriber_config_t", typeof(SubscriberConfig) }, { "octocap_stream_info_t", typeof(StreamInfo) },
            { "octocap_detector_config_t", typeof(DetectorConfig) }, { "octocap_image_t", typeof(Image) },
            { "octocap_detect_info_t", typeof(DetectInfo) }, { "octocap_frame_summary_t", typeof(FrameSummary) },
            { "octocap_person_t", typeof(Person) }, { "octocap_live_config_t", typeof(LiveConfig) },
            { "octocap_live_stats_t", typeof(LiveStats) }, { "octocap_camera_status_t", typeof(CameraStatus) },
        };

        static string Pascal(string snake)
        {
            var sb = new StringBuilder();
            foreach (string part in snake.Split('_'))
                if (part.Length > 0) sb.Append(char.ToUpperInvariant(part[0])).Append(part.Substring(1));
            return sb.ToString();
        }

        [Test]
        public void EveryStructMatchesTheCHeader()
        {
            int fields = 0;
            var seen = new HashSet<string>();
            foreach (string line in TestEnv.RunDump("layout").Split(new[] { '\n' }, StringSplitOptions.RemoveEmptyEntries))
            {
                string[] p = line.Split(' ');
                Assert.IsTrue(Mirrors.ContainsKey(p[0]), "no C# mirror for " + p[0]);
                Type t = Mirrors[p[0]];
                seen.Add(p[0]);
                int expected = int.Parse(p[2]);
                if (p[1] == "sizeof")
                {
                    Assert.AreEqual(expected, Marshal.SizeOf(t), "sizeof " + p[0]);
                    continue;
                }
                string name = Pascal(p[1]);
                Assert.IsNotNull(t.GetField(name), p[0] + "." + p[1] + " has no C# field " + name);
                Assert.AreEqual(expected, (int)Marshal.OffsetOf(t, name), "offset of " + p[0] + "." + p[1]);
                ++fields;
            }
            Assert.AreEqual(Mirrors.Count, seen.Count);
            Assert.Greater(fields, 40);
            // And the C# side has no field the C side lacks.
            int csFields = 0;
            foreach (Type t in Mirrors.Values) csFields += t.GetFields(System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.Instance).Length;
            Assert.AreEqual(fields, csFields);
        }

        [Test]
        public void DefaultConfigCarriesItsSize()
        {
            SessionConfig c = SessionConfig.Default;
            Assert.AreEqual((uint)Marshal.SizeOf(typeof(SessionConfig)), c.StructSize);
            Assert.AreEqual(Method.Auto, c.Method);
            Assert.AreEqual(Filter.OneEuro, c.Filter);
        }
    }
}
