// Live capture in Unity: cameras (devices, rtsp://, http://, or files) opened and solved on octocap's own threads;
// the game loop only reads the newest frame (OctocapAvatarDriver via IFrameSource), so capture and detection never
// cost a frame of the game. Prefer this to OctocapCameraRig, which detects from WebCamTextures on the main thread.
using System;
using Octocap;
using UnityEngine;

public sealed class OctocapLiveRig : MonoBehaviour
{
    public string calibrationPath = "calibration.toml";
    /// <summary>One per calibrated camera, in calibration order: "/dev/video0" or "0", "rtsp://...", "http://...",
    /// a video file or a picture folder.</summary>
    public string[] cameras = new string[0];
    /// <summary>"" : movenet-thunder, which the governor trades for movenet-lightning when even one view a set is
    /// too slow.</summary>
    public string model = "";
    public DetectMode mode = DetectMode.Crop;
    /// <summary>At most this many views run the network each set, the others followed by optical flow (0: every view;
    /// the governor then decides how many, docs/benchmarks.md "Real time").</summary>
    public int viewsPerFrame = 0;
    /// <summary>Governed: hold targetFps (0: the cameras' rate) with bounded latency, trading detection for rate; Max: every
    /// view detected, whatever the rate.</summary>
    public LiveQuality quality = LiveQuality.Governed;
    public float targetFps = 0;
    /// <summary>Auto: the GPU when the GPU build of ONNX Runtime and a GPU are there, else the CPU.</summary>
    public Device device = Device.Auto;
    /// <summary>Avatars driven by this capture (each by its bindBy and person: Slot 0, 1, ... one person each).</summary>
    public OctocapAvatarDriver[] avatars = new OctocapAvatarDriver[0];

    public Live Live { get; private set; }
    Calibration _calibration;

    void Start()
    {
        Library.CheckVersion();
        _calibration = Calibration.Load(calibrationPath);
        SessionConfig session = SessionConfig.Default;
        session.Layout = Layout.Coco17;  // the shipped models' layout
        LiveConfig config = LiveConfig.Default;
        config.Quality = quality;
        config.TargetFps = Math.Max(0f, targetFps);
        Live = new Live(config, session, _calibration, cameras);
        DetectorConfig detector = DetectorConfig.Default;
        detector.SetModel(model);
        detector.Mode = mode;
        detector.ViewsPerFrame = (uint)Math.Max(0, viewsPerFrame);
        detector.Device = device;
        Live.SetDetector(detector);
        Live.Start();  // an OctocapException names a camera that cannot be opened
        foreach (var avatar in avatars)
            if (avatar != null) avatar.Source = Live;
    }

    void OnDestroy()
    {
        foreach (var avatar in avatars)
            if (avatar != null && avatar.Source == Live) avatar.Source = null;
        Live?.Dispose();
        _calibration?.Dispose();
    }
}
