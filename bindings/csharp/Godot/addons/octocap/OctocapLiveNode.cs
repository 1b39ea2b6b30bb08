// Live capture in Godot: cameras opened and solved on octocap's own threads; skeleton drivers read the newest frame
// each _Process without waiting.
using Godot;
using Octocap;

public partial class OctocapLiveNode : Node
{
    [Export] public string CalibrationPath = "calibration.toml";
    /// <summary>One per calibrated camera, in calibration order: "/dev/video0", "rtsp://...", "http://...", a file.</summary>
    [Export] public string[] Cameras = new string[0];
    /// <summary>"" : movenet-thunder, which the governor trades for movenet-lightning when even one view a set is
    /// too slow.</summary>
    [Export] public string Model = "";
    /// <summary>At most this many views run the network each set, the others followed by optical flow (0: every view;
    /// the governor then decides how many, docs/benchmarks.md "Real time").</summary>
    [Export] public int ViewsPerFrame = 0;
    /// <summary>Governed: hold TargetFps (0: the cameras' rate) with bounded latency, trading detection for rate; Max: every
    /// view detected, whatever the rate.</summary>
    [Export] public LiveQuality Quality = LiveQuality.Governed;
    [Export] public float TargetFps = 0;
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
        LiveConfig config = LiveConfig.Default;
        config.Quality = Quality;
        config.TargetFps = System.Math.Max(0f, TargetFps);
        Live = new Live(config, session, _calibration, Cameras);
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
