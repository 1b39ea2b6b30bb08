using System;

namespace Octocap.Avatar
{
    /// <summary>Quaternion arithmetic on <see cref="Quat"/>, so the avatar logic needs no engine types.</summary>
    public static class QuatMath
    {
        public static readonly Quat Identity = new Quat(0, 0, 0, 1);

        public static Quat Multiply(Quat a, Quat b) => new Quat(
            a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
            a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X,
            a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W,
            a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);

        public static Quat Conjugate(Quat q) => new Quat(-q.X, -q.Y, -q.Z, q.W);

        public static Quat Normalize(Quat q)
        {
            float n = (float)Math.Sqrt(q.X * q.X + q.Y * q.Y + q.Z * q.Z + q.W * q.W);
            return n > 0 ? new Quat(q.X / n, q.Y / n, q.Z / n, q.W / n) : Identity;
        }

        public static Quat FromAxisAngle(float x, float y, float z, float radians)
        {
            float n = (float)Math.Sqrt(x * x + y * y + z * z);
            float s = (float)Math.Sin(radians / 2) / n;
            return new Quat(x * s, y * s, z * s, (float)Math.Cos(radians / 2));
        }

        public static float Dot(Quat a, Quat b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;

        /// <summary>Angle (radians) of the rotation taking a to b.</summary>
        public static float Angle(Quat a, Quat b)
        {
            float d = Math.Min(1f, Math.Abs(Dot(Normalize(a), Normalize(b))));
            return 2f * (float)Math.Acos(d);
        }

        /// <summary>Spherical interpolation along the shorter arc.</summary>
        public static Quat Slerp(Quat a, Quat b, float t)
        {
            float d = Dot(a, b);
            if (d < 0) { b = new Quat(-b.X, -b.Y, -b.Z, -b.W); d = -d; }
            if (d > 0.9995f)
                return Normalize(new Quat(a.X + t * (b.X - a.X), a.Y + t * (b.Y - a.Y), a.Z + t * (b.Z - a.Z), a.W + t * (b.W - a.W)));
            float th = (float)Math.Acos(d), s = (float)Math.Sin(th);
            float wa = (float)Math.Sin((1 - t) * th) / s, wb = (float)Math.Sin(t * th) / s;
            return new Quat(wa * a.X + wb * b.X, wa * a.Y + wb * b.Y, wa * a.Z + wb * b.Z, wa * a.W + wb * b.W);
        }

        /// <summary>Rotates vector (x, y, z) by q.</summary>
        public static void Rotate(Quat q, ref float x, ref float y, ref float z)
        {
            Quat r = Multiply(Multiply(q, new Quat(x, y, z, 0)), Conjugate(q));
            x = r.X; y = r.Y; z = r.Z;
        }
    }
}
