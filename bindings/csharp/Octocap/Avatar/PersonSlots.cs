using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;

namespace Octocap.Avatar
{
    /// <summary>How a driver picks its person from each frame.</summary>
    public enum BindPersonBy
    {
        /// <summary>The n-th person to appear, kept while tracked (see <see cref="PersonSlots"/>). With several
        /// people this is what an avatar wants: it does not jump to someone else when another person leaves.</summary>
        Slot = 0,
        /// <summary>The person whose id (octocap_person_t.id) is n; nobody once they are gone for good.</summary>
        Id = 1,
        /// <summary>The n-th person of each frame in id order: changes hands whenever someone comes or goes.</summary>
        Index = 2,
    }

    /// <summary>Avatar slots for the people of a source, as octocap's VMC output assigns its ports: a person keeps
    /// their slot while tracked, a newcomer takes the lowest free slot (people arriving together in id order), a
    /// slot whose person went is free again. Every driver of one source shares one (<see cref="For"/>), so two avatars
    /// never take the same person; it moves on only when the source's frame changes.</summary>
    public sealed class PersonSlots
    {
        static readonly ConditionalWeakTable<IFrameSource, PersonSlots> Shared = new ConditionalWeakTable<IFrameSource, PersonSlots>();

        readonly List<uint> _ids = new List<uint>();  // per slot; 0 = free
        long _lastFrame = long.MinValue;
        uint _lastDefinition;

        /// <summary>The slots of <paramref name="source"/>, shared by everything that reads it.</summary>
        public static PersonSlots For(IFrameSource source)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            return Shared.GetValue(source, s => new PersonSlots());
        }

        /// <summary>The person id in <paramref name="slot"/>, 0 when the slot is free.</summary>
        public uint IdOf(int slot) => slot >= 0 && slot < _ids.Count ? _ids[slot] : 0;

        /// <summary>Assigns the slots from the ids of this frame's people (any order).</summary>
        public void Update(IReadOnlyList<uint> ids)
        {
            if (ids == null) throw new ArgumentNullException(nameof(ids));
            for (int s = 0; s < _ids.Count; ++s)
                if (_ids[s] != 0 && !Contains(ids, _ids[s])) _ids[s] = 0;
            var sorted = new List<uint>(ids);
            sorted.Sort();
            foreach (uint id in sorted)
            {
                if (id == 0 || _ids.Contains(id)) continue;
                int free = _ids.IndexOf(0);
                if (free < 0) _ids.Add(id);
                else _ids[free] = id;
            }
        }

        /// <summary>Assigns the slots from <paramref name="frame"/>, once per frame of the source (a frame already
        /// seen, as when several drivers read the same newest frame, changes nothing).</summary>
        public void Update(Frame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            FrameSummary s = frame.Summary;
            if (s.FrameIndex == _lastFrame && s.DefinitionCounter == _lastDefinition) return;
            _lastFrame = s.FrameIndex;
            _lastDefinition = s.DefinitionCounter;
            var ids = new uint[s.PersonCount];
            for (int i = 0; i < ids.Length; ++i) ids[i] = frame.GetPerson(i).Id;
            Update(ids);
        }

        /// <summary>Index in <paramref name="frame"/> of the person <paramref name="by"/> and <paramref name="n"/>
        /// choose, or -1 when that person is not in it.</summary>
        public static int Resolve(IFrameSource source, Frame frame, BindPersonBy by, int n)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (n < 0) return -1;
            int count = frame.PersonCount;
            if (by == BindPersonBy.Index) return n < count ? n : -1;
            uint id = (uint)n;
            if (by == BindPersonBy.Slot)
            {
                PersonSlots slots = For(source);
                slots.Update(frame);
                id = slots.IdOf(n);
            }
            if (id == 0) return -1;
            for (int i = 0; i < count; ++i)
                if (frame.GetPerson(i).Id == id) return i;
            return -1;
        }

        static bool Contains(IReadOnlyList<uint> ids, uint id)
        {
            for (int i = 0; i < ids.Count; ++i)
                if (ids[i] == id) return true;
            return false;
        }
    }
}
