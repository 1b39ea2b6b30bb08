// Thin Unity adapter: N webcams (WebCamTexture, in the calibration's camera order) in, solved frames out. Update only
// copies the pictures (WebCamTexture can be read on the main thread alone) into a BackgroundSolver's image set, as
// RGBA8 with Unity's bottom-up rows turned top-down, and submits it without waiting: detection and the solve run on
// the solver's thread, so the game keeps its frame rate whatever the detector costs. Pairs with OctocapAvatarDriver
// (its Source is this rig's Solver).
using System;
using Octocap;
using UnityEngine;

public sealed class OctocapCameraRig : MonoBehaviour
{
    [Tooltip("Calibration TOML (anipose / Pose2Sim), cameras in the same order as the webcams below")]
    public string calibrationPath = "calibration.toml";
    [Tooltip("Webcam device names, in calibration order")]
    public string[] deviceNames = new string[0];
    [Tooltip("Shipped model name (movenet-thunder, movenet-lightning, movenet-multipose) or an .onnx path")]
    public string model = "";
    public DetectMode mode = DetectMode.Crop;
    [Tooltip("ONNX Runtime threads (0 = all cores)")]
    public int detectorThreads = 0;
    public OctocapAvatarDriver avatar;

    public Session Session { get; private set; }
    public BackgroundSolver Solver { get; private set; }

    Calibration _calibration;
    WebCamTexture[] _cams;
    Color32[][] _pixels;

    void Start()
    {
        Library.CheckVersion();
        _calibration = Calibration.Load(calibrationPath);
        if (_calibration.CameraCount != deviceNames.Length)
            throw new OctocapException(Result.CameraMismatch, "the calibration has " + _calibration.CameraCount +
                                       " cameras, " + deviceNames.Length + " webcams are configured");
        SessionConfig cfg = SessionConfig.Default;
        cfg.Layout = Layout.Coco17;  // the shipped models' layout
        Session = new Session(cfg, _calibration);
        DetectorConfig detector = DetectorConfig.Default;
        detector.SetModel(model);
        detector.Mode = mode;
        detector.Threads = (uint)Math.Max(0, detectorThreads);
        Session.SetDetector(detector);
        Solver = new BackgroundSolver(Session, deviceNames.Length);
        if (avatar != null) avatar.Source = Solver;
        _cams = new WebCamTexture[deviceNames.Length];
        _pixels = new Color32[deviceNames.Length][];
        for (int i = 0; i < _cams.Length; ++i)
        {
            _cams[i] = new WebCamTexture(deviceNames[i]);
            _cams[i].Play();
        }
    }

    unsafe void Update()
    {
        if (Solver == null) return;
        foreach (var cam in _cams)
            if (!cam.didUpdateThisFrame) return;  // a set when every view has a new picture
        BackgroundSolver.ImageSet set = Solver.Rent();
        for (int i = 0; i < _cams.Length; ++i)
        {
            int w = _cams[i].width, h = _cams[i].height;
            if (_pixels[i] == null || _pixels[i].Length != w * h) _pixels[i] = new Color32[w * h];
            _cams[i].GetPixels32(_pixels[i]);
            // Unity's rows start at the bottom; the detector's at the top.
            fixed (Color32* src = _pixels[i])
            fixed (byte* dst = set.Resize(i, w, h))
                for (int y = 0; y < h; ++y)
                    Buffer.MemoryCopy(src + (h - 1 - y) * w, dst + y * w * 4, w * 4, w * 4);
        }
        set.Format = PixelFormat.Rgba8;
        set.TimestampUs = (long)(Time.timeAsDouble * 1e6);
        Solver.Submit(set);  // never waits: a set the solver had no time for is replaced by this one
        if (Solver.LastError != null) Debug.LogWarning("octocap: " + Solver.LastError);
    }

    void OnDestroy()
    {
        if (_cams != null)
            foreach (var cam in _cams)
                if (cam != null) cam.Stop();
        Solver?.Dispose();  // joins the worker before the session goes
        Session?.Dispose();
        _calibration?.Dispose();
    }
}
