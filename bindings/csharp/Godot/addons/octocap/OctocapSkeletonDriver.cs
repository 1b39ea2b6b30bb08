// Thin Godot 4 adapter: reads octocap bones in Godot's frame and poses a Skeleton3D by bone name. The logic
// (names, retargeting, smoothing) is in Octocap.Avatar, engine-free and tested.
using Godot;
using Octocap;
using Octocap.Avatar;

public partial class OctocapSkeletonDriver : Node3D
{
    [Export] public NodePath SkeletonPath;
    [Export] public float Smoothing = 0.3f;
    /// <summary>Skeleton bone name per octocap bone (BoneId order); empty = Godot's humanoid profile names.</summary>
    [Export] public string[] BoneNameOverrides = new string[0];

    /// <summary>How <see cref="Person"/> picks who drives this skeleton: Slot (default: the n-th person to appear,
    /// kept while tracked, so the skeleton never jumps to someone else), Id (octocap's person id), or Index (the n-th
    /// person of each frame). Several skeletons can share a source: with Slot 0, 1, 2 ... each gets its own person.</summary>
    [Export] public BindPersonBy BindBy = BindPersonBy.Slot;
    [Export] public int Person = 0;

    /// <summary>Where frames come from: a Session or a Subscriber; the driver only reads it.</summary>
    public IFrameSource Source { get; set; }

    readonly AvatarRetargeter _retargeter = new AvatarRetargeter();
    readonly BonePose[] _bones = new BonePose[(int)BoneId.Count];
    Skeleton3D _skeleton;
    int[] _index;
    int[] _spine;  // Chest, UpperChest: whichever the skeleton has; octocap's torso is spread over them and Spine

    public override void _Ready()
    {
        Library.CheckVersion();
        _skeleton = GetNode<Skeleton3D>(SkeletonPath);
        _index = new int[(int)BoneId.Count];
        for (int b = 0; b < _index.Length; ++b)
        {
            string name = b < BoneNameOverrides.Length && BoneNameOverrides[b] != "" ? BoneNameOverrides[b] : BoneNames.GodotHumanoid[b];
            _index[b] = _skeleton.FindBone(name);
        }
        var spine = new System.Collections.Generic.List<int>();
        foreach (string name in new[] { "Chest", "UpperChest" })
            if (_skeleton.FindBone(name) >= 0) spine.Add(_skeleton.FindBone(name));
        _spine = spine.ToArray();
    }

    /// <summary>Call with the skeleton in its T-pose.</summary>
    public void CalibrateTPose()
    {
        var rest = new Quat[_index.Length];
        var present = new bool[_index.Length];
        for (int b = 0; b < _index.Length; ++b)
        {
            present[b] = _index[b] >= 0;
            rest[b] = present[b] ? ToOctocap(_skeleton.GetBoneGlobalPose(_index[b]).Basis.GetRotationQuaternion()) : QuatMath.Identity;
        }
        _retargeter.CalibrateTPose(rest, present);
        var spineRest = new Quat[_spine.Length];
        for (int i = 0; i < _spine.Length; ++i)
            spineRest[i] = ToOctocap(_skeleton.GetBoneGlobalPose(_spine[i]).Basis.GetRotationQuaternion());
        _retargeter.CalibrateSpine(spineRest);
    }

    public override void _Process(double delta)
    {
        if (Source == null || !_retargeter.IsCalibrated) return;
        if (!FrameReader.TryReadBones(Source, BindBy, Person, CoordFrame.Godot, _bones)) return;  // nobody yet: hold the pose
        _retargeter.Smoothing = Smoothing;
        Quat[] world = _retargeter.Update(_bones);
        // Parents come before children in BoneId order, so each parent's new global pose is already set.
        for (int b = 0; b < _index.Length; ++b)
        {
            if (_index[b] >= 0 && _retargeter.Drives((BoneId)b)) SetGlobalRotation(_index[b], world[b]);
            if (b == (int)BoneId.Torso)  // the chest bones above Spine, before the neck and shoulders that hang off them
                for (int i = 0; i < _spine.Length; ++i) SetGlobalRotation(_spine[i], _retargeter.SpineOutput[i]);
        }
    }

    void SetGlobalRotation(int bone, Quat world)
    {
        int parent = _skeleton.GetBoneParent(bone);
        Quaternion parentGlobal = parent >= 0 ? _skeleton.GetBoneGlobalPose(parent).Basis.GetRotationQuaternion() : Quaternion.Identity;
        _skeleton.SetBonePoseRotation(bone, parentGlobal.Inverse() * ToGodot(world));
    }

    static Quaternion ToGodot(Quat q) => new Quaternion(q.X, q.Y, q.Z, q.W);
    static Quat ToOctocap(Quaternion q) => new Quat(q.X, q.Y, q.Z, q.W);
}
