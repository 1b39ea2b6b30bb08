using System;
using System.IO;
using NUnit.Framework;

namespace Octocap.Tests
{
    [TestFixture]
    public class KeystoreTests
    {
        /// <summary>A keystore made from C# gives each identity the role it was added with; an existing identity and a
        /// missing folder are refused with the native message; and a config secures nothing until told to.</summary>
        [Test]
        public unsafe void IdentitiesKeepTheirRoles()
        {
            string dir = TestEnv.TempFile("keystore");
            try
            {
                Keystore.Create(dir);
                Assert.IsTrue(File.Exists(Path.Combine(dir, "ca.pem")));
                string hub = Keystore.AddIdentity(dir, "hub", SecurityRole.Hub);
                string viewer = Keystore.AddIdentity(dir, "viewer", SecurityRole.Viewer, 30);
                Assert.AreEqual(Path.Combine(dir, "hub"), hub);
                Assert.AreEqual(SecurityRole.Hub, Keystore.CheckIdentity(hub));
                Assert.AreEqual(SecurityRole.Viewer, Keystore.CheckIdentity(viewer));

                var e = Assert.Throws<OctocapException>(() => Keystore.AddIdentity(dir, "hub", SecurityRole.Node));
                Assert.AreEqual(Result.InvalidArgument, e.Result);
                StringAssert.Contains(hub, e.Message);
                // The refused add left the hub as it was.
                Assert.AreEqual(SecurityRole.Hub, Keystore.CheckIdentity(hub));

                string missing = Path.Combine(dir, "nobody");
                e = Assert.Throws<OctocapException>(() => Keystore.CheckIdentity(missing));
                Assert.AreEqual(Result.Io, e.Result);
                StringAssert.Contains(missing, e.Message);
            }
            finally
            {
                if (Directory.Exists(dir)) Directory.Delete(dir, true);
            }

            // Plain DDS unless a folder is given: a 1.9 caller's stream must not turn secure.
            SessionConfig session = SessionConfig.Default;
            LiveConfig live = LiveConfig.Default;
            SubscriberConfig sub = SubscriberConfig.Default;
            Assert.AreEqual(0, session.StreamSecurity[0]);
            Assert.AreEqual(0u, session.Reserved110);
            Assert.AreEqual(0, live.RemoteSecurity[0]);
            Assert.AreEqual(0, sub.Security[0]);
            sub.SetSecurity("ks/viewer");
            Assert.AreEqual((byte)'k', sub.Security[0]);
            Assert.AreEqual(0, sub.Security[9]);
            SessionConfig tooLong = SessionConfig.Default;
            Assert.Throws<ArgumentException>(() => tooLong.SetStreamSecurity(new string('x', 512)));
        }
    }
}
