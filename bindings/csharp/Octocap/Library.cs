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

        public static string Version => NativeMethods.Utf8(NativeMethods.octocap_version());

        /// <summary>Throws when the native library was built for another ABI than these bindings.</summary>
        public static void CheckAbi()
        {
            uint native = NativeMethods.octocap_abi_version();
            if (native != AbiVersion)
                throw new OctocapException(Result.Unsupported, "liboctocap has ABI " + native + ", these bindings expect " + AbiVersion);
        }

        public static int KeypointCount(Layout layout) => (int)NativeMethods.octocap_layout_keypoint_count(layout);
        public static string KeypointName(Layout layout, int index) =>
            NativeMethods.Utf8(NativeMethods.octocap_layout_keypoint_name(layout, (uint)index));

        public static unsafe BoneInfo GetBoneInfo(BoneId bone)
        {
            BoneInfo info;
            OctocapException.Check(NativeMethods.octocap_bone_info((uint)bone, out info));
            return info;
        }

        public static unsafe string BoneName(BoneId bone)
        {
            BoneInfo info = GetBoneInfo(bone);
            return Marshal.PtrToStringAnsi((IntPtr)info.Name);
        }

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
