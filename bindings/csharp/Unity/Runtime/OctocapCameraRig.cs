// Thin Unity adapter: N webcams (WebCamTexture, in the calibration's camera order) in, a solved frame out, every
// Update. Pairs with OctocapAvatarDriver (give it this rig's Session). Pixels go to the native detector pinned, as
// RGBA8, with Unity's bottom-up rows copied into the top-down order the detector expects.
using System;
using System.Runtime.InteropServices;
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

    Calibration _calibration;
    WebCamTexture[] _cams;
    Color32[][] _pixels;
    byte[][] _topDown;

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
        if (avatar != null) avatar.Source = Session;
        _cams = new WebCamTexture[deviceNames.Length];
        _pixels = new Color32[deviceNames.Length][];
        _topDown = new byte[deviceNames.Length][];
        for (int i = 0; i < _cams.Length; ++i)
        {
            _cams[i] = new WebCamTexture(deviceNames[i]);
            _cams[i].Play();
        }
    }

    unsafe void Update()
    {
        if (Session == null) return;
        foreach (var cam in _cams)
            if (!cam.didUpdateThisFrame) return;  // solve when every view has a new picture
        var images = new Image[_cams.Length];
        var pins = new GCHandle[_cams.Length];
        try
        {
            for (int i = 0; i < _cams.Length; ++i)
            {
                int w = _cams[i].width, h = _cams[i].height;
                if (_pixels[i] == null || _pixels[i].Length != w * h)
                {
                    _pixels[i] = new Color32[w * h];
                    _topDown[i] = new byte[w * h * 4];
                }
                _cams[i].GetPixels32(_pixels[i]);
                // Unity's rows start at the bottom; the detector's at the top.
                fixed (Color32* src = _pixels[i])
                fixed (byte* dst = _topDown[i])
                    for (int y = 0; y < h; ++y)
                        Buffer.MemoryCopy(src + (h - 1 - y) * w, dst + y * w * 4, w * 4, w * 4);
                pins[i] = GCHandle.Alloc(_topDown[i], GCHandleType.Pinned);
                images[i] = new Image { Pixels = pins[i].AddrOfPinnedObject(), Width = (uint)w, Height = (uint)h,
                                        StrideBytes = (uint)(w * 4), Format = PixelFormat.Rgba8 };
            }
            // Ok or NoPerson (nobody in view: a normal outcome); errors throw.
            Session.SolveImages(images, (long)(Time.timeAsDouble * 1e6));
        }
        finally
        {
            foreach (var pin in pins)
                if (pin.IsAllocated) pin.Free();
        }
    }

    void OnDestroy()
    {
        if (_cams != null)
            foreach (var cam in _cams)
                if (cam != null) cam.Stop();
        Session?.Dispose();
        _calibration?.Dispose();
    }
}
