#if TOOLS
using Godot;

[Tool]
public partial class OctocapPlugin : EditorPlugin
{
    public override void _EnterTree()
    {
        AddCustomType("OctocapSkeletonDriver", "Node3D", GD.Load<Script>("res://addons/octocap/OctocapSkeletonDriver.cs"), null);
    }

    public override void _ExitTree() => RemoveCustomType("OctocapSkeletonDriver");
}
#endif
