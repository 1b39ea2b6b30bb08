namespace Octocap.Avatar
{
    /// <summary>Which engine bone each octocap bone drives. The rotation of an octocap bone turns the segment from
    /// its head joint to its tail joint, so it goes to the engine bone that sits at the head joint.</summary>
    public static class BoneNames
    {
        /// <summary>Unity's HumanBodyBones member names, indexed by <see cref="BoneId"/>.</summary>
        public static readonly string[] UnityHumanBodyBones =
        {
            "Hips", "Spine", "Neck", "RightShoulder", "RightUpperArm", "RightLowerArm", "LeftShoulder",
            "LeftUpperArm", "LeftLowerArm", "RightUpperLeg", "RightLowerLeg", "LeftUpperLeg", "LeftLowerLeg",
            "RightFoot", "LeftFoot", "RightHand", "LeftHand"
        };

        /// <summary>Godot 4's SkeletonProfileHumanoid bone names (what retargeted humanoids use), by <see cref="BoneId"/>.</summary>
        public static readonly string[] GodotHumanoid =
        {
            "Hips", "Spine", "Neck", "RightShoulder", "RightUpperArm", "RightLowerArm", "LeftShoulder",
            "LeftUpperArm", "LeftLowerArm", "RightUpperLeg", "RightLowerLeg", "LeftUpperLeg", "LeftLowerLeg",
            "RightFoot", "LeftFoot", "RightHand", "LeftHand"
        };
    }
}
