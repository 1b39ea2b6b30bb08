// Thin Unity adapter: reads octocap bones in Unity's frame and writes Humanoid bone transforms. All mapping,
// retargeting and smoothing logic is in Octocap.Avatar (engine-free, tested); this file only touches Unity.
using System;
using Octocap;
using Octocap.Avatar;
using UnityEngine;
using UnityEngine.Serialization;

[RequireComponent(typeof(Animator))]
public sealed class OctocapAvatarDriver : MonoBehaviour
{
    [Range(0f, 0.95f)] public float smoothing = 0.3f;
    public bool driveRootPosition = true;
    public Vector3 rootOffset = Vector3.zero;

    /// <summary>How <see cref="person"/> picks who drives this avatar: Slot (default: the n-th person to appear,
    /// kept while tracked, so the avatar never jumps to someone else), Id (octocap's person id), or Index (the n-th
    /// person of each frame). Several avatars can share a source: with Slot 0, 1, 2 ... each gets its own person.</summary>
    public BindPersonBy bindBy = BindPersonBy.Slot;
    [FormerlySerializedAs("personIndex")] public int person = 0;

    /// <summary>Where frames come from: a local Session (fed by your detector or OctocapCameraRig) or a Subscriber
    /// (a stream from another machine). The driver only reads it.</summary>
    public IFrameSource Source { get; set; }

    readonly AvatarRetargeter _retargeter = new AvatarRetargeter();
    readonly BonePose[] _bones = new BonePose[(int)BoneId.Count];
    Transform[] _targets;
    Transform[] _spine;  // Chest, UpperChest: whichever the avatar has; octocap's torso is spread over them and Spine

    void Awake()
    {
        Library.CheckVersion();
        var animator = GetComponent<Animator>();
        _targets = new Transform[(int)BoneId.Count];
        for (int b = 0; b < _targets.Length; ++b)
        {
            var hb = (HumanBodyBones)Enum.Parse(typeof(HumanBodyBones), BoneNames.UnityHumanBodyBones[b]);
            _targets[b] = animator.GetBoneTransform(hb);
        }
        var spine = new System.Collections.Generic.List<Transform>();
        foreach (var hb in new[] { HumanBodyBones.Chest, HumanBodyBones.UpperChest })
            if (animator.GetBoneTransform(hb) != null) spine.Add(animator.GetBoneTransform(hb));
        _spine = spine.ToArray();
    }

    /// <summary>Call with the avatar standing in a T-pose (arms out, facing +Z).</summary>
    [ContextMenu("T-pose calibrate")]
    public void CalibrateTPose()
    {
        var rest = new Quat[_targets.Length];
        var present = new bool[_targets.Length];
        for (int b = 0; b < _targets.Length; ++b)
        {
            present[b] = _targets[b] != null;
            rest[b] = present[b] ? ToOctocap(_targets[b].rotation) : QuatMath.Identity;
        }
        _retargeter.CalibrateTPose(rest, present);
        var spineRest = new Quat[_spine.Length];
        for (int i = 0; i < _spine.Length; ++i) spineRest[i] = ToOctocap(_spine[i].rotation);
        _retargeter.CalibrateSpine(spineRest);
    }

    void LateUpdate()
    {
        if (Source == null || !_retargeter.IsCalibrated) return;
        if (!FrameReader.TryReadBones(Source, bindBy, person, CoordFrame.Unity, _bones)) return;  // nobody yet: hold the pose
        _retargeter.Smoothing = smoothing;
        Quat[] world = _retargeter.Update(_bones);
        // Parents before children: Spine, then the chest bones above it, then the neck and shoulders.
        for (int b = 0; b < _targets.Length; ++b)
        {
            if (_targets[b] != null && _retargeter.Drives((BoneId)b)) _targets[b].rotation = ToUnity(world[b]);
            if (b == (int)BoneId.Torso)
                for (int i = 0; i < _spine.Length; ++i) _spine[i].rotation = ToUnity(_retargeter.SpineOutput[i]);
        }
        BonePose root = _bones[(int)BoneId.Root];
        if (driveRootPosition && root.Valid != 0 && _targets[0] != null)
            _targets[0].position = new Vector3(root.HeadPosition.X, root.HeadPosition.Y, root.HeadPosition.Z) + rootOffset;
    }

    static Quaternion ToUnity(Quat q) => new Quaternion(q.X, q.Y, q.Z, q.W);
    static Quat ToOctocap(Quaternion q) => new Quat(q.x, q.y, q.z, q.w);
}
