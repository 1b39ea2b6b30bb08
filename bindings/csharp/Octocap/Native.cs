// P/Invoke declarations and blittable structs mirroring sdk/include/octocap/octocap.h field for field.
// tests/StructLayoutTests.cs checks every size and offset against the C compiler's.
using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    /// <summary>octocap_result_t: Ok, positive statuses for normal outcomes that produced nothing, negative errors.</summary>
    public enum Result : int
    {
        Ok = 0, NoPerson = 1, Timeout = 2,
        InvalidArgument = -1, InvalidHandle = -2, StructSize = -3, Io = -4, Parse = -5,
        BufferTooSmall = -6, CameraMismatch = -7, NotEnoughViews = -8, NoResult = -9, Unsupported = -10,
        OutOfMemory = -11, Internal = -99
    }

    /// <summary>Three floats (metres or a unit direction), laid out as C's float[3].</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3
    {
        public float X, Y, Z;
        public Vec3(float x, float y, float z) { X = x; Y = y; Z = z; }
        public override string ToString() => "(" + X + ", " + Y + ", " + Z + ")";
    }

    /// <summary>A fixed 32-byte, NUL-terminated UTF-8 name (C's char[32]), read without unsafe code.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct Name32
    {
        fixed byte _bytes[32];
        public override string ToString()
        {
            fixed (byte* b = _bytes) return NativeMethods.Utf8((IntPtr)b, 32);
        }
    }

    /// <summary>A char[OCTOCAP_ERROR_TEXT_CAPACITY] field: an error's text, UTF-8, NUL-terminated ("" none).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct ErrorText
    {
        public const int Capacity = 256;
        fixed byte _bytes[Capacity];
        public override string ToString()
        {
            fixed (byte* b = _bytes) return NativeMethods.Utf8((IntPtr)b, Capacity);
        }
    }

    public enum LogLevel : int { Debug = 0, Info = 1, Warning = 2, Error = 3 }
    public enum Layout : int { Auto = 0, Body25 = 1, Body25B = 2, Coco17 = 3, Halpe26 = 4, BlazePose33 = 5 }
    public enum Method : int { Subdivision = 0, Triangulation = 1, Auto = 2 }
    public enum Filter : int { None = 0, OneEuro = 1, OneEuroFixed = 2 }
    public enum UpAxis : int { Y = 0, Z = 1, Auto = 2 }
    public enum CoordFrame : int { Rig = 0, Unity = 1, Godot = 2 }
    public enum StreamQos : int { Live = 0, Record = 1 }
    public enum PixelFormat : int { Rgb8 = 0, Bgr8 = 1, Rgba8 = 2 }
    public enum DetectMode : int { PerView = 0, Mosaic = 1, Crop = 2 }
    /// <summary>Where the detector's network runs (octocap_device_t, 1.5).</summary>
    public enum Device : int { Cpu = 0, Auto = 1, Cuda = 2 }
    /// <summary>(1.9) The inference back end: Auto is OpenVINO on the CPU where the library has it, else ONNX Runtime.</summary>
    public enum Runtime : int { Auto = 0, OnnxRuntime = 1, OpenVino = 2 }
    /// <summary>(1.9) The network's arithmetic: Auto (bf16 where the CPU has it natively and the back end can), F32, Reduced.</summary>
    public enum Precision : int { Auto = 0, F32 = 1, Reduced = 2 }
    public enum PersonPick : int { All = 0, Largest = 1, MostConfident = 2, NearestPrevious = 3 }
    /// <summary>(1.10) What a keystore identity may do on the network (octocap_security_role_t): a Node publishes 2D
    /// keypoints, a Hub reads them and publishes skeletons (a live engine, a session that streams), a Viewer reads
    /// skeletons.</summary>
    public enum SecurityRole : int { Node = 0, Hub = 1, Viewer = 2 }

    /// <summary>The skeleton joints (octocap_joint_id_t): the paper's 14 and a root, then toes, heels and knuckles (1.4).</summary>
    public enum JointId : int
    {
        Head = 0, Neck, RShoulder, RElbow, RHand, LShoulder, LElbow, LHand, RHip, RKnee, RFoot, LHip, LKnee, LFoot,
        Root, RToe, LToe, RHeel, LHeel, RKnuckles, LKnuckles, Count
    }

    /// <summary>Rig bones (octocap_bone_id_t); parents come before children.</summary>
    public enum BoneId : int
    {
        Root = 0, Torso, Head, RShoulder, RUpperArm, RLowerArm, LShoulder, LUpperArm, LLowerArm, RUpperLeg,
        RLowerLeg, LUpperLeg, LLowerLeg, RFoot, LFoot, RHand, LHand, Count
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Keypoint2D
    {
        public float X, Y, Confidence;
        public Keypoint2D(float x, float y, float confidence) { X = x; Y = y; Confidence = confidence; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Joint
    {
        public Vec3 Position;
        public float Confidence;
        public float ReprojectionErrorPx;
        public uint ViewsUsed;
        public uint Valid;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Quat
    {
        public float X, Y, Z, W;
        public Quat(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct BonePose
    {
        public Quat LocalRotation;
        public Quat GlobalRotation;
        public Vec3 HeadPosition;
        public float LengthM;
        public uint Valid;
    }

    /// <summary>octocap_frame_info_t (0.x; frames give <see cref="FrameSummary"/> and <see cref="Person"/>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrameInfo
    {
        public long FrameIndex;
        public long TimestampUs;
        public uint KeypointsSolved;
        public uint KeypointsTotal;
        public float MeanReprojectionErrorPx;
        public uint ViewsWithPerson;
        public float SolveMs;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct BoneInfo
    {
        public Name32 Name;
        public int ParentBone;
        public int HeadJoint;
        public int TailJoint;
        public Vec3 RestDirection;
    }

    /// <summary>octocap_frame_summary_t: what a frame holds.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrameSummary
    {
        public uint StructSize;
        public uint PersonCount;
        public long FrameIndex;
        public long TimestampUs;
        public Layout Layout;
        public uint KeypointCount;
        public uint DefinitionCounter;
        public uint SourceId;
        public uint ViewCount;
        public uint JointsInRigFrame;
        public float SolveMs;
    }

    /// <summary>octocap_person_t: one person of a frame.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Person
    {
        public uint StructSize;
        public uint Id;
        public uint KeypointsSolved;
        public uint KeypointsTotal;
        public uint JointsSolved;
        public uint ViewsWithPerson;
        public float MeanReprojectionErrorPx;
        public float Confidence;
        /// <summary>(1.11) Feet planted on the floor this frame: <see cref="FootRight"/>, <see cref="FootLeft"/>.</summary>
        public uint FootContacts;

        /// <summary>FootContacts: the right foot is planted (OCTOCAP_FOOT_RIGHT).</summary>
        public const uint FootRight = 1;
        /// <summary>FootContacts: the left foot is planted (OCTOCAP_FOOT_LEFT).</summary>
        public const uint FootLeft = 2;
        public bool RightFootPlanted => (FootContacts & FootRight) != 0;
        public bool LeftFootPlanted => (FootContacts & FootLeft) != 0;
    }

    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct CameraData
    {
        public fixed byte Name[32];
        public uint Width;
        public uint Height;
        public fixed double Matrix[9];
        public fixed double Distortion[5];
        public uint Fisheye;
        public fixed double Rotation[3];
        public fixed double Translation[3];
    }

    /// <summary>octocap_session_config_t. Start from <see cref="SessionConfig.Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct SessionConfig
    {
        public uint StructSize;
        public Layout Layout;
        public Method Method;
        public Filter Filter;
        public UpAxis UpAxis;
        public uint Sigma;
        public uint MinViews;
        public float DeltaM;
        public float PixelTolerance;
        public uint MaxCandidates;
        public float MinConfidence;
        public float OutlierThresholdPx;
        public Vec3 VolumeMin;
        public Vec3 VolumeMax;
        public float FilterMinCutoffHz;
        public float FilterBeta;
        public uint WorkerThreads;
        public long FirstFrameIndex;
        public uint StreamEnable;
        public uint StreamDomainId;
        public StreamQos StreamQos;
        public uint StreamHistoryDepth;
        public uint StreamSourceId;
        public fixed byte StreamTopic[32];
        public uint VmcPort;
        public fixed byte VmcHost[64];
        /// <summary>People per frame: 1 (default) one person; N up to N, tracked with stable ids; 0 everyone (up to 16).</summary>
        public uint MaxPeople;
        /// <summary>(1.10) Unused: it fills what was 1.3's padding, which a 1.3 caller never zeroed.</summary>
        public uint Reserved110;
        /// <summary>(1.10) "" (default): the stream is plain DDS; a keystore identity folder (role Hub): DDS Security.</summary>
        public fixed byte StreamSecurity[512];
        /// <summary>(1.11) 0 (default): joints as solved; 1: a planted foot holds still (its ankle, knee and foot).</summary>
        public uint FootLock;
        /// <summary>(1.11) Unused: keeps the struct free of padding.</summary>
        public uint Reserved111;

        /// <summary>The library's defaults for this struct's size (octocap_session_config_defaults).</summary>
        public static SessionConfig Default
        {
            get
            {
                var c = new SessionConfig();
                OctocapException.Check(NativeMethods.octocap_session_config_defaults(ref c, (uint)sizeof(SessionConfig)));
                return c;
            }
        }

        /// <summary>The DDS topic base name (UTF-8, at most 31 bytes).</summary>
        public void SetStreamTopic(string topic)
        {
            fixed (byte* t = StreamTopic) NativeMethods.CopyUtf8(topic, t, 32, "stream topic");
        }

        /// <summary>The VMC receiver's host (UTF-8, at most 63 bytes).</summary>
        public void SetVmcHost(string host)
        {
            fixed (byte* h = VmcHost) NativeMethods.CopyUtf8(host, h, 64, "VMC host");
        }

        /// <summary>(1.10) The stream's keystore identity folder (KEYSTORE/NAME, <see cref="Keystore.AddIdentity"/>,
        /// role Hub); null or "" for plain DDS.</summary>
        public void SetStreamSecurity(string identityDir)
        {
            fixed (byte* s = StreamSecurity) NativeMethods.CopyUtf8(identityDir ?? "", s, 512, "stream security folder");
        }
    }

    /// <summary>octocap_detector_config_t, given to <see cref="Session.SetDetector"/> or a detector.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct DetectorConfig
    {
        public uint StructSize;
        public fixed byte Model[512];
        public DetectMode Mode;
        public PersonPick PersonPick;
        public uint Threads;
        public uint MosaicTilePx;
        public uint MaxPeople;
        public float MinConfidence;
        public uint ParallelViews;
        /// <summary>(1.5) Views detected each frame, the others followed by optical flow; 0 = every view.</summary>
        public uint ViewsPerFrame;
        /// <summary>(1.5) Cpu (default), Auto (the GPU when there is one) or Cuda (the GPU or an error).</summary>
        public Device Device;
        /// <summary>(1.9) The inference back end (default Auto).</summary>
        public Runtime Runtime;
        /// <summary>(1.9) Its arithmetic (default Auto).</summary>
        public Precision Precision;

        /// <summary>A shipped model's name ("movenet-thunder") or an .onnx path; null or "" for the mode's default.</summary>
        public void SetModel(string model)
        {
            fixed (byte* m = Model) NativeMethods.CopyUtf8(model ?? "", m, 512, "model path");
        }

        /// <summary>The library's defaults for this struct's size (octocap_detector_config_defaults).</summary>
        public static DetectorConfig Default
        {
            get
            {
                var c = new DetectorConfig();
                OctocapException.Check(NativeMethods.octocap_detector_config_defaults(ref c, (uint)sizeof(DetectorConfig)));
                return c;
            }
        }
    }

    /// <summary>octocap_image_t: a camera image the caller keeps alive (pinned) for the duration of the call.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Image
    {
        public IntPtr Pixels;
        public uint Width;
        public uint Height;
        public uint StrideBytes;
        public PixelFormat Format;
    }

    /// <summary>octocap_detect_info_t.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct DetectInfo
    {
        public uint StructSize;
        public float TotalMs;
        public float PreprocessMs;
        public float InferenceMs;
        public uint Inferences;
        public Layout Layout;
        public uint KeypointCount;
        public Name32 Model;
        public DetectMode Mode;
        public uint ViewsTracked;
        public float TrackMs;
        public Device Device;
        public Runtime Runtime;
        public Precision Precision;
    }

    /// <summary>octocap_subscriber_config_t. Start from <see cref="SubscriberConfig.Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct SubscriberConfig
    {
        public uint StructSize;
        public uint DomainId;
        public StreamQos Qos;
        public uint HistoryDepth;
        public uint SourceId;
        public fixed byte Topic[32];
        /// <summary>(1.10) "" (default): plain DDS; a keystore identity folder (role Viewer or Hub): DDS Security.</summary>
        public fixed byte Security[512];

        public static SubscriberConfig Default
        {
            get
            {
                var c = new SubscriberConfig();
                OctocapException.Check(NativeMethods.octocap_subscriber_config_defaults(ref c, (uint)sizeof(SubscriberConfig)));
                return c;
            }
        }

        /// <summary>The DDS topic base name (UTF-8, at most 31 bytes).</summary>
        public void SetTopic(string topic)
        {
            fixed (byte* t = Topic) NativeMethods.CopyUtf8(topic, t, 32, "topic");
        }

        /// <summary>(1.10) The subscriber's keystore identity folder (role Viewer or Hub); null or "" for plain DDS. The
        /// publisher must be secured alike, or the two never meet.</summary>
        public void SetSecurity(string identityDir)
        {
            fixed (byte* s = Security) NativeMethods.CopyUtf8(identityDir ?? "", s, 512, "security folder");
        }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct StreamInfo
    {
        public ulong FramesReceived;
        public ulong FramesLost;
        public ulong LastGap;
        public ulong Restarts;
        public ulong Rejected;
        public uint SourceId;
        public uint DefinitionCounter;
        public Layout Layout;
        public uint HasDefinition;
    }

    /// <summary>octocap_live_config_t. Start from <see cref="LiveConfig.Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct LiveConfig
    {
        public uint StructSize;
        public uint SyncToleranceUs;
        public uint MaxWaitUs;
        public uint OpenTimeoutMs;
        public uint ReadTimeoutMs;
        public uint ReconnectMaxMs;
        public float PictureRateHz;
        // 1.1: where remote cameras (dds://NODE/CAMERA, capture nodes' keypoints) are read.
        public uint RemoteDomainId;
        public Name32 RemoteTopic;
        /// <summary>1.8. Governed (default): hold TargetFps within LatencyBudgetMs, choosing each set how much detection
        /// it gets; Max: every set detected as the detector config says.</summary>
        public LiveQuality Quality;
        /// <summary>1.8. Sets a second the governor holds; 0 (default): the slowest camera's rate.</summary>
        public float TargetFps;
        /// <summary>1.8. Grab to frame, ms, that the governor keeps sets within. Default 100.</summary>
        public uint LatencyBudgetMs;
        /// <summary>(1.10) "" (default): remote cameras over plain DDS; a keystore identity folder (role Hub): DDS
        /// Security, from nodes of the same keystore only.</summary>
        public fixed byte RemoteSecurity[512];

        public static LiveConfig Default
        {
            get
            {
                var c = new LiveConfig();
                OctocapException.Check(NativeMethods.octocap_live_config_defaults(ref c, (uint)Marshal.SizeOf(typeof(LiveConfig))));
                return c;
            }
        }

        /// <summary>(1.10) The keystore identity folder remote cameras are read with (role Hub); null or "" for plain DDS.</summary>
        public void SetRemoteSecurity(string identityDir)
        {
            fixed (byte* s = RemoteSecurity) NativeMethods.CopyUtf8(identityDir ?? "", s, 512, "remote security folder");
        }
    }

    /// <summary>octocap_live_stats_t: times are means over the frames solved so far.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LiveStats
    {
        public uint StructSize;
        public uint Running;
        public uint Finished;
        public uint CameraCount;
        public ulong FrameSets;
        public ulong FramesWithPerson;
        public ulong SetsIncomplete;
        public ulong FramesNotTaken;
        public float Fps;
        public float CaptureMs;
        public float DetectMs;
        public float SolveMs;
        public float PublishMs;
        public float LatencyP50Ms;
        public float LatencyP99Ms;
        // 1.2
        public ulong SetsRecorded;
        public ulong RecordingPicturesDropped;
        /// <summary>1.6. 1: the engine stopped on an error it cannot go on from, said in LastError.</summary>
        public uint Failed;
        /// <summary>1.6. The last error: what failed the engine, a set that could not be solved, a recording's write error.</summary>
        public ErrorText LastError;
        // 1.8: the rate governor's choice for the last set.
        /// <summary>1.8. Its rung of the quality ladder, 0 the best.</summary>
        public uint QualityRung;
        /// <summary>1.8. Rungs of the ladder; 0: not governed.</summary>
        public uint QualityRungs;
        /// <summary>1.8. Views the network ran on in the last set (the others followed by optical flow).</summary>
        public uint ViewsDetected;
        public float TargetFps;
        /// <summary>1.8. Smoothed cost of the sets over what a set may cost; above 1 the governor steps down.</summary>
        public float BudgetUsed;
        public uint RungChanges;
        /// <summary>1.8. The model card's name of the network that ran the last set.</summary>
        public Name32 Model;
        /// <summary>1.13. Cameras the last set held; CameraCount for a complete set.</summary>
        public uint ViewsInSet;
    }

    /// <summary>octocap_live_quality_t (1.8).</summary>
    public enum LiveQuality : int { Governed = 0, Max = 1 }

    public enum CameraState : int { Stopped = 0, Connecting = 1, Streaming = 2, Reconnecting = 3, Ended = 4, Failed = 5 }

    /// <summary>octocap_camera_status_t.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct CameraStatus
    {
        public uint StructSize;
        public CameraState State;
        public ulong Grabbed;
        public ulong Used;
        public ulong Dropped;
        public ulong Reconnects;
        public float Fps;
        public float NominalFps;
        public Name32 Name;
        /// <summary>1.1. Remote cameras: transit plus how far the node's clock lags this host's (ms).</summary>
        public float ClockOffsetMs;
        /// <summary>1.4. 1: capture times from the stream's own timestamps; 0: from when the host grabbed each picture.</summary>
        public uint StreamClock;
        /// <summary>1.6. Why the camera last failed to open or broke ("" never); kept after it reconnected.</summary>
        public ErrorText LastError;
        /// <summary>1.7. Pictures received but left out as undecodable (corrupt, not a picture); the camera goes on.</summary>
        public ulong BadPictures;
    }

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    internal delegate void NativeLogCallback(LogLevel level, IntPtr message, IntPtr user);

    internal static unsafe class NativeMethods
    {
        const string Lib = "octocap";

        [DllImport(Lib)] internal static extern IntPtr octocap_version();
        [DllImport(Lib)] internal static extern uint octocap_abi_version();
        [DllImport(Lib)] internal static extern IntPtr octocap_last_error();
        [DllImport(Lib)] internal static extern void octocap_set_log_callback(NativeLogCallback cb, LogLevel min, IntPtr user);

        [DllImport(Lib)] internal static extern uint octocap_layout_keypoint_count(Layout layout);
        [DllImport(Lib)] internal static extern IntPtr octocap_layout_keypoint_name(Layout layout, uint index);
        [DllImport(Lib)] internal static extern Result octocap_bone_info(uint bone, out BoneInfo info);

        [DllImport(Lib)] internal static extern Result octocap_calibration_load(byte[] path, out CalibrationHandle calib);
        [DllImport(Lib)] internal static extern Result octocap_calibration_create(CameraData* cameras, uint count, out CalibrationHandle calib);
        [DllImport(Lib)] internal static extern Result octocap_calibration_save(CalibrationHandle calib, byte[] path);
        [DllImport(Lib)] internal static extern Result octocap_calibration_camera_count(CalibrationHandle calib, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_calibration_get_camera(CalibrationHandle calib, uint index, out CameraData camera);
        [DllImport(Lib)] internal static extern Result octocap_calibration_project(CalibrationHandle calib, uint index, double* world, double* pixel);
        [DllImport(Lib)] internal static extern void octocap_calibration_destroy(IntPtr calib);

        [DllImport(Lib)] internal static extern uint octocap_version_number();
        [DllImport(Lib)] internal static extern Result octocap_session_config_defaults(ref SessionConfig cfg, uint structSize);
        [DllImport(Lib)] internal static extern Result octocap_detector_config_defaults(ref DetectorConfig cfg, uint structSize);
        [DllImport(Lib)] internal static extern Result octocap_session_set_detector(SessionHandle s, ref DetectorConfig cfg);
        [DllImport(Lib)] internal static extern Result octocap_session_get_frame(SessionHandle s, out FrameHandle frame);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_summary(FrameHandle f, ref FrameSummary summary);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_person(FrameHandle f, uint person, ref Person p);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_keypoints3d(FrameHandle f, uint person, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_joints(FrameHandle f, uint person, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_bones(FrameHandle f, uint person, CoordFrame frame, BonePose* bones, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_frame_get_person_views(FrameHandle f, uint person, int* views, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern void octocap_frame_release(IntPtr frame);
        [DllImport(Lib)] internal static extern Result octocap_motion_get_frame(MotionHandle motion, uint index, out FrameHandle frame);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_take_frame(SubscriberHandle sub, int timeoutMs, out FrameHandle frame);
        [DllImport(Lib)] internal static extern Result octocap_session_create(ref SessionConfig cfg, CalibrationHandle calib, out SessionHandle session);
        [DllImport(Lib)] internal static extern void octocap_session_destroy(IntPtr session);
        [DllImport(Lib)] internal static extern Result octocap_session_solve_keypoints(SessionHandle s, Keypoint2D* keypoints, uint* peoplePerView, uint viewCount, long timestampUs);
        [DllImport(Lib)] internal static extern Result octocap_session_solve_images(SessionHandle s, Image* images, uint viewCount, long timestampUs);
        [DllImport(Lib)] internal static extern Result octocap_session_detections(SessionHandle s, uint view, Keypoint2D* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_detect_info(SessionHandle s, ref DetectInfo info);
        [DllImport(Lib)] internal static extern IntPtr octocap_onnxruntime_version();
        [DllImport(Lib)] internal static extern IntPtr octocap_openvino_version();
        [DllImport(Lib)] internal static extern Result octocap_session_reset(SessionHandle s);
        [DllImport(Lib)] internal static extern Result octocap_session_flush_stream(SessionHandle s);
        [DllImport(Lib)] internal static extern Result octocap_session_stream_subscribers(SessionHandle s, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_method(SessionHandle s, out Method method);
        [DllImport(Lib)] internal static extern Result octocap_session_up_axis(SessionHandle s, out UpAxis up);
        [DllImport(Lib)] internal static extern Result octocap_session_get_frame_info(SessionHandle s, out FrameInfo info);
        [DllImport(Lib)] internal static extern Result octocap_session_get_keypoints3d(SessionHandle s, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_get_joints(SessionHandle s, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_get_selected_people(SessionHandle s, int* people, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_get_bones(SessionHandle s, CoordFrame frame, BonePose* bones, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_definition_counter(SessionHandle s, out uint counter);

        [DllImport(Lib)] internal static extern Result octocap_recording_open(byte[] directory, Layout layout, out RecordingHandle rec);
        [DllImport(Lib)] internal static extern void octocap_recording_destroy(IntPtr rec);
        [DllImport(Lib)] internal static extern Result octocap_motion_open(byte[] path, out MotionHandle motion);
        [DllImport(Lib)] internal static extern void octocap_motion_destroy(IntPtr motion);
        [DllImport(Lib)] internal static extern Result octocap_motion_info(MotionHandle motion, out uint frameCount, out double rateHz);
        [DllImport(Lib)] internal static extern Result octocap_motion_joints(MotionHandle motion, uint frame, Joint* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_motion_bones(MotionHandle motion, uint frame, CoordFrame coordFrame, BonePose* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_view_count(RecordingHandle rec, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_frame_count(RecordingHandle rec, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_layout(RecordingHandle rec, out Layout layout);
        [DllImport(Lib)] internal static extern Result octocap_recording_read_frame(RecordingHandle rec, uint frame, Keypoint2D* keypoints, uint capacity, out uint keypointCount, uint* peoplePerView, uint viewCount);

        [DllImport(Lib)] internal static extern Result octocap_live_config_defaults(ref LiveConfig cfg, uint structSize);
        [DllImport(Lib)] internal static extern Result octocap_live_create(ref LiveConfig cfg, ref SessionConfig sessionCfg, CalibrationHandle calib, IntPtr[] cameras, uint count, out LiveHandle live);
        [DllImport(Lib)] internal static extern Result octocap_live_set_detector(LiveHandle live, ref DetectorConfig cfg);
        [DllImport(Lib)] internal static extern Result octocap_live_set_latency_offsets(LiveHandle live, int[] offsetsUs, uint count);
        [DllImport(Lib)] internal static extern Result octocap_live_set_recording(LiveHandle live, byte[] directory);
        [DllImport(Lib)] internal static extern Result octocap_live_start(LiveHandle live);
        [DllImport(Lib)] internal static extern Result octocap_live_stop(LiveHandle live);
        [DllImport(Lib)] internal static extern void octocap_live_destroy(IntPtr live);
        [DllImport(Lib)] internal static extern Result octocap_live_take_frame(LiveHandle live, int timeoutMs, out FrameHandle frame);
        [DllImport(Lib)] internal static extern Result octocap_live_get_frame(LiveHandle live, out FrameHandle frame);
        [DllImport(Lib)] internal static extern Result octocap_live_get_stats(LiveHandle live, ref LiveStats stats);
        [DllImport(Lib)] internal static extern Result octocap_live_get_camera_status(LiveHandle live, uint index, ref CameraStatus status);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_config_defaults(ref SubscriberConfig cfg, uint structSize);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_create(ref SubscriberConfig cfg, out SubscriberHandle sub);
        [DllImport(Lib)] internal static extern void octocap_subscriber_destroy(IntPtr sub);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_take(SubscriberHandle sub, int timeoutMs);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_stream_info(SubscriberHandle sub, out StreamInfo info);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_frame_info(SubscriberHandle sub, out FrameInfo info);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_keypoints3d(SubscriberHandle sub, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_joints(SubscriberHandle sub, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_bones(SubscriberHandle sub, CoordFrame frame, BonePose* bones, uint capacity, out uint count);

        [DllImport(Lib)] internal static extern Result octocap_keystore_create(byte[] dir, uint validDays);
        [DllImport(Lib)] internal static extern Result octocap_keystore_add_identity(byte[] dir, byte[] name, SecurityRole role, uint validDays);
        [DllImport(Lib)] internal static extern Result octocap_keystore_check_identity(byte[] identityDir, out SecurityRole role);

        // Strings cross the boundary as UTF-8 both ways (never the platform's ANSI code page: Windows paths with
        // non-ASCII names must reach the library intact).
        internal static string Utf8(IntPtr p, int max = int.MaxValue)
        {
            if (p == IntPtr.Zero) return null;
            byte* b = (byte*)p;
            int n = 0;
            while (n < max && b[n] != 0) ++n;
            return System.Text.Encoding.UTF8.GetString(b, n);
        }

        internal static byte[] Utf8Z(string s)
        {
            if (s == null) throw new ArgumentNullException(nameof(s));
            int n = System.Text.Encoding.UTF8.GetByteCount(s);
            var bytes = new byte[n + 1];
            System.Text.Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        internal static void CopyUtf8(string s, byte* dst, int capacity, string what)
        {
            byte[] utf8 = System.Text.Encoding.UTF8.GetBytes(s ?? "");
            if (utf8.Length >= capacity)
                throw new ArgumentException(what + " is longer than " + (capacity - 1) + " UTF-8 bytes", nameof(s));
            for (int i = 0; i < capacity; ++i) dst[i] = i < utf8.Length ? utf8[i] : (byte)0;
        }
    }
}
