using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>Marks a static method as called from native code, for IL2CPP / AOT (Unity's MonoPInvokeCallback,
    /// defined here so the library needs no engine assembly; IL2CPP matches it by name).</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type delegateType) { DelegateType = delegateType; }
        public Type DelegateType { get; }
    }

    /// <summary>Process-wide library facts: version, layouts, the skeleton definition, logging.</summary>
    public static class Library
    {
        public const uint AbiVersion = 1;
        /// <summary>The header version these bindings mirror (OCTOCAP_VERSION_NUMBER: major * 10000 + minor * 100 + patch).</summary>
        public const uint BindingsVersionNumber = 11100;

        public static string Version => NativeMethods.Utf8(NativeMethods.octocap_version());
        public static uint VersionNumber => NativeMethods.octocap_version_number();

        /// <summary>Throws unless the native library can serve these bindings: the same ABI line and major version,
        /// and not older than the header they mirror (a newer library keeps working with older bindings).</summary>
        public static void CheckVersion()
        {
            uint abi = NativeMethods.octocap_abi_version();
            if (abi != AbiVersion)
                throw new OctocapException(Result.Unsupported, "liboctocap has ABI " + abi + ", these bindings expect " + AbiVersion);
            uint native = VersionNumber;
            if (native / 10000 != BindingsVersionNumber / 10000 || native < BindingsVersionNumber)
                throw new OctocapException(Result.Unsupported, "liboctocap is " + Version + ", these bindings need " +
                                           BindingsVersionNumber / 10000 + ".x, at least " + BindingsVersionNumber / 10000 +
                                           "." + BindingsVersionNumber / 100 % 100);
        }

        [Obsolete("Use CheckVersion")]
        public static void CheckAbi() => CheckVersion();

        public static int KeypointCount(Layout layout) => (int)NativeMethods.octocap_layout_keypoint_count(layout);
        public static string KeypointName(Layout layout, int index) =>
            NativeMethods.Utf8(NativeMethods.octocap_layout_keypoint_name(layout, (uint)index));

        public static unsafe BoneInfo GetBoneInfo(BoneId bone)
        {
            BoneInfo info;
            OctocapException.Check(NativeMethods.octocap_bone_info((uint)bone, out info));
            return info;
        }

        public static string BoneName(BoneId bone) => GetBoneInfo(bone).Name.ToString();

        // The delegate handed to native code must outlive every call into it: held here, never collected.
        static readonly NativeLogCallback s_trampoline = Trampoline;
        static Action<LogLevel, string> s_handler;

        /// <summary>Receives the library's log (null removes the handler). May be called from any thread.</summary>
        public static void SetLogHandler(Action<LogLevel, string> handler, LogLevel minLevel = LogLevel.Info)
        {
            s_handler = handler;
            NativeMethods.octocap_set_log_callback(handler == null ? null : s_trampoline, minLevel, IntPtr.Zero);
        }

        [MonoPInvokeCallback(typeof(NativeLogCallback))]
        static void Trampoline(LogLevel level, IntPtr message, IntPtr user)
        {
            var h = s_handler;
            // An exception must not unwind into native code.
            try { h?.Invoke(level, NativeMethods.Utf8(message)); } catch (Exception) { }
        }
    }
}
