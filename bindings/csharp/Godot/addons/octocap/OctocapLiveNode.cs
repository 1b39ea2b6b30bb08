// Live capture in Godot: cameras opened and solved on octocap's own threads; skeleton drivers read the newest frame
// each _Process without waiting.
using Godot;
using Octocap;

public partial class OctocapLiveNode : Node
{
    [Export] public string CalibrationPath = "calibration.toml";
    /// <summary>One per calibrated camera, in calibration order: "/dev/video0", "rtsp://...", "http://...", a file.</summary>
    [Export] public string[] Cameras = new string[0];
    [Export] public string Model = "movenet-lightning";
    /// <summary>Views the network runs on each set, the others followed by optical flow (0: every view). Live use
    /// favours the rate: with four cameras, 2 doubles it for ~2 mm (README "Real time").</summary>
    [Export] public int ViewsPerFrame = 2;
    /// <summary>Auto: the GPU when the GPU build of ONNX Runtime and a GPU are there, else the CPU.</summary>
    [Export] public Device Device = Device.Auto;
    [Export] public NodePath[] Drivers = new NodePath[0];

    public Live Live { get; private set; }
    Calibration _calibration;

    public override void _Ready()
    {
        Library.CheckVersion();
        _calibration = Calibration.Load(ProjectSettings.GlobalizePath(CalibrationPath));
        SessionConfig session = SessionConfig.Default;
        session.Layout = Layout.Coco17;
        Live = new Live(LiveConfig.Default, session, _calibration, Cameras);
        DetectorConfig detector = DetectorConfig.Default;
        detector.SetModel(Model);
        detector.ViewsPerFrame = (uint)System.Math.Max(0, ViewsPerFrame);
        detector.Device = Device;
        Live.SetDetector(detector);
        Live.Start();
        foreach (NodePath path in Drivers)
            if (GetNode(path) is OctocapSkeletonDriver driver) driver.Source = Live;
    }

    public override void _ExitTree()
    {
        Live?.Dispose();
        _calibration?.Dispose();
    }
}
