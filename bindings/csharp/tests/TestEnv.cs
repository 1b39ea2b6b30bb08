using System;
using System.Diagnostics;
using System.IO;

namespace Octocap.Tests
{
    /// <summary>Paths handed in by run-tests.sh, and a runner for the C side (octocap-abi-dump).</summary>
    static class TestEnv
    {
        public static string Sample => Require("OCTOCAP_SAMPLE_DIR");
        public static string AbiDump => Require("OCTOCAP_ABI_DUMP");
        public static string Root => Require("OCTOCAP_SOURCE_DIR");

        static string Require(string name)
        {
            string v = Environment.GetEnvironmentVariable(name);
            if (string.IsNullOrEmpty(v)) throw new InvalidOperationException(name + " is not set (run bindings/csharp/run-tests.sh)");
            return v;
        }

        public static string RunDump(string args)
        {
            var psi = new ProcessStartInfo(AbiDump, args) { RedirectStandardOutput = true, UseShellExecute = false };
            using (var p = Process.Start(psi))
            {
                string output = p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                if (p.ExitCode != 0) throw new InvalidOperationException("octocap-abi-dump " + args + " failed");
                return output;
            }
        }

        public static string TempFile(string name) => Path.Combine(Path.GetTempPath(), "octocap_cs_" + Guid.NewGuid().ToString("N") + "_" + name);
    }
}
