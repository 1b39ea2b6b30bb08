using System;

namespace Octocap
{
    /// <summary>A set of calibrated cameras (anipose / Pose2Sim TOML).</summary>
    public sealed class Calibration : IDisposable
    {
        internal readonly CalibrationHandle Handle;

        Calibration(CalibrationHandle h) { Handle = h; }

        public static Calibration Load(string path)
        {
            CalibrationHandle h;
            OctocapException.Check(NativeMethods.octocap_calibration_load(NativeMethods.Utf8Z(path), out h));
            return new Calibration(h);
        }

        public static unsafe Calibration Create(CameraData[] cameras)
        {
            if (cameras == null) throw new ArgumentNullException(nameof(cameras));
            CalibrationHandle h;
            fixed (CameraData* p = cameras)
                OctocapException.Check(NativeMethods.octocap_calibration_create(p, (uint)cameras.Length, out h));
            return new Calibration(h);
        }

        public void Save(string path) => OctocapException.Check(NativeMethods.octocap_calibration_save(Handle, NativeMethods.Utf8Z(path)));

        public int CameraCount
        {
            get
            {
                uint n;
                OctocapException.Check(NativeMethods.octocap_calibration_camera_count(Handle, out n));
                return (int)n;
            }
        }

        public CameraData GetCamera(int index)
        {
            CameraData c;
            OctocapException.Check(NativeMethods.octocap_calibration_get_camera(Handle, (uint)index, out c));
            return c;
        }

        /// <summary>World point (metres) to pixel in camera <paramref name="index"/>, with distortion.</summary>
        public unsafe void Project(int index, double x, double y, double z, out double u, out double v)
        {
            double* w = stackalloc double[3];
            double* p = stackalloc double[2];
            w[0] = x; w[1] = y; w[2] = z;
            OctocapException.Check(NativeMethods.octocap_calibration_project(Handle, (uint)index, w, p));
            u = p[0];
            v = p[1];
        }

        public void Dispose() => Handle.Dispose();
    }
}
