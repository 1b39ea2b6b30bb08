using System;

namespace Octocap.Avatar
{
    /// <summary>What an engine driver does each engine frame, engine-free: take the source's newest frame and read
    /// one person's bones. No exception for the normal cases (nothing solved yet, nobody in view, that person
    /// absent); errors (a disposed source, a bad buffer) still throw.</summary>
    public static class FrameReader
    {
        /// <summary>Fills <paramref name="bones"/> (BoneId.Count entries) with person <paramref name="person"/> of
        /// the source's newest frame; false, <paramref name="bones"/> untouched, when there is no such frame or person.</summary>
        public static bool TryReadBones(IFrameSource source, int person, CoordFrame frame, BonePose[] bones)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (bones == null || bones.Length < (int)BoneId.Count)
                throw new ArgumentException("bones needs " + (int)BoneId.Count + " entries", nameof(bones));
            using (Frame f = source.TryGetFrame())
            {
                if (f == null || person < 0 || person >= f.PersonCount) return false;
                f.GetBones(person, frame, bones);
                return true;
            }
        }
    }
}
