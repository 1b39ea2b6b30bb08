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

        /// <summary>The same for the person <paramref name="by"/> and <paramref name="n"/> choose: a slot (the n-th
        /// person to appear, kept while tracked), an id, or an index.</summary>
        public static bool TryReadBones(IFrameSource source, BindPersonBy by, int n, CoordFrame frame, BonePose[] bones)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (bones == null || bones.Length < (int)BoneId.Count)
                throw new ArgumentException("bones needs " + (int)BoneId.Count + " entries", nameof(bones));
            using (Frame f = source.TryGetFrame())
            {
                if (f == null) return false;
                int person = PersonSlots.Resolve(source, f, by, n);
                if (person < 0) return false;
                f.GetBones(person, frame, bones);
                return true;
            }
        }
    }
}
