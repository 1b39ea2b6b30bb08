namespace Octocap
{
    /// <summary>(1.10) A DDS Security keystore (octocap_keystore_*): one CA signs an identity per participant, so that
    /// only the keystore's identities read or write the stream, each as its role allows. A participant is given its
    /// identity folder (KEYSTORE/NAME) through <see cref="SessionConfig.SetStreamSecurity"/>,
    /// <see cref="LiveConfig.SetRemoteSecurity"/> or <see cref="SubscriberConfig.SetSecurity"/>. The CA's private key
    /// (KEYSTORE/ca.key.pem) is needed only to add identities: keep it off the capture machines.</summary>
    public static class Keystore
    {
        /// <summary>Makes a keystore in <paramref name="dir"/> (created if missing, readable by its owner only), valid
        /// for <paramref name="validDays"/> (1 .. 36500). Throws for a folder that holds a keystore already: a new CA
        /// would orphan its identities.</summary>
        public static void Create(string dir, uint validDays = 3650) =>
            OctocapException.Check(NativeMethods.octocap_keystore_create(NativeMethods.Utf8Z(dir), validDays));

        /// <summary>Adds identity <paramref name="name"/> (1 to 64 letters, digits, '-', '_', '.') with
        /// <paramref name="role"/> to the keystore <paramref name="dir"/>, as DIR/NAME; returns that folder. Throws for
        /// an identity that exists.</summary>
        public static string AddIdentity(string dir, string name, SecurityRole role, uint validDays = 365)
        {
            OctocapException.Check(NativeMethods.octocap_keystore_add_identity(NativeMethods.Utf8Z(dir), NativeMethods.Utf8Z(name),
                                                                               role, validDays));
            return System.IO.Path.Combine(dir, name);
        }

        /// <summary>Checks an identity folder as a participant does before it joins and returns its role; throws naming
        /// the file and the cause (missing, not what it should be, expired, not signed by the keystore's CA).</summary>
        public static SecurityRole CheckIdentity(string identityDir)
        {
            SecurityRole role;
            OctocapException.Check(NativeMethods.octocap_keystore_check_identity(NativeMethods.Utf8Z(identityDir), out role));
            return role;
        }
    }
}
