// P/Invoke declarations and blittable structs mirroring sdk/include/octocap/octocap.h field for field.
// tests/StructLayoutTests.cs checks every size and offset against the C compiler's.
using System;
using System.Runtime.InteropServices;

namespace Octocap
{
    public enum Result : int
    {
        Ok = 0, InvalidArgument = -1, InvalidHandle = -2, StructSize = -3, Io = -4, Parse = -5,
        BufferTooSmall = -6, CameraMismatch = -7, NotEnoughViews = -8, NoResult = -9, Unsupported = -10,
        Internal = -99
    }

    public enum LogLevel : int { Debug = 0, Info = 1, Warning = 2, Error = 3 }
    public enum Layout : int { Auto = 0, Body25 = 1, Body25B = 2, Coco17 = 3, Halpe26 = 4 }
    public enum Method : int { Subdivision = 0, Triangulation = 1, Auto = 2 }
    public enum Filter : int { None = 0, OneEuro = 1 }
    public enum UpAxis : int { Y = 0, Z = 1, Auto = 2 }
    public enum CoordFrame : int { Rig = 0, Unity = 1, Godot = 2 }
    public enum StreamQos : int { Live = 0, Record = 1 }
    public enum PixelFormat : int { Rgb8 = 0, Bgr8 = 1, Rgba8 = 2 }
    public enum DetectMode : int { PerView = 0, Mosaic = 1, Crop = 2 }
    public enum PersonPick : int { All = 0, Largest = 1, MostConfident = 2, NearestPrevious = 3 }

    /// <summary>The paper's skeleton joints (octocap_joint_id_t).</summary>
    public enum JointId : int
    {
        Head = 0, Neck, RShoulder, RElbow, RHand, LShoulder, LElbow, LHand, RHip, RKnee, RFoot, LHip, LKnee, LFoot,
        Root, Count
    }

    /// <summary>Rig bones (octocap_bone_id_t); parents come before children.</summary>
    public enum BoneId : int
    {
        Root = 0, Torso, Head, RShoulder, RUpperArm, RLowerArm, LShoulder, LUpperArm, LLowerArm, RUpperLeg,
        RLowerLeg, LUpperLeg, LLowerLeg, Count
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Keypoint2D
    {
        public float X, Y, Confidence;
        public Keypoint2D(float x, float y, float confidence) { X = x; Y = y; Confidence = confidence; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct Joint
    {
        public fixed float Position[3];
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
    public unsafe struct BonePose
    {
        public Quat LocalRotation;
        public Quat GlobalRotation;
        public fixed float HeadPosition[3];
        public float LengthM;
        public uint Valid;
    }

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
    public unsafe struct BoneInfo
    {
        public fixed byte Name[32];
        public int ParentBone;
        public int HeadJoint;
        public int TailJoint;
        public fixed float RestDirection[3];
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
        public fixed float VolumeMin[3];
        public fixed float VolumeMax[3];
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
        public DetectorConfig Detector;

        /// <summary>The library's defaults (octocap_session_config_init), struct_size set.</summary>
        public static SessionConfig Default
        {
            get
            {
                SessionConfig c;
                NativeMethods.octocap_session_config_init(out c);
                return c;
            }
        }
    }

    /// <summary>octocap_detector_config_t (also nested in <see cref="SessionConfig"/>).</summary>
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

        /// <summary>A shipped model's name ("movenet-thunder") or an .onnx path; null or "" for the mode's default.</summary>
        public void SetModel(string model)
        {
            byte[] utf8 = System.Text.Encoding.UTF8.GetBytes(model ?? "");
            if (utf8.Length >= 512) throw new OctocapException(Result.InvalidArgument, "model path is longer than 511 bytes");
            fixed (byte* m = Model)
            {
                for (int i = 0; i < 512; ++i) m[i] = i < utf8.Length ? utf8[i] : (byte)0;
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
    public unsafe struct DetectInfo
    {
        public uint StructSize;
        public float TotalMs;
        public float PreprocessMs;
        public float InferenceMs;
        public uint Inferences;
        public Layout Layout;
        public uint KeypointCount;
        public fixed byte Model[32];
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

        public static SubscriberConfig Default
        {
            get
            {
                SubscriberConfig c;
                NativeMethods.octocap_subscriber_config_init(out c);
                return c;
            }
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

        [DllImport(Lib)] internal static extern Result octocap_calibration_load(string path, out CalibrationHandle calib);
        [DllImport(Lib)] internal static extern Result octocap_calibration_create(CameraData* cameras, uint count, out CalibrationHandle calib);
        [DllImport(Lib)] internal static extern Result octocap_calibration_save(CalibrationHandle calib, string path);
        [DllImport(Lib)] internal static extern Result octocap_calibration_camera_count(CalibrationHandle calib, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_calibration_get_camera(CalibrationHandle calib, uint index, out CameraData camera);
        [DllImport(Lib)] internal static extern Result octocap_calibration_project(CalibrationHandle calib, uint index, double* world, double* pixel);
        [DllImport(Lib)] internal static extern void octocap_calibration_destroy(IntPtr calib);

        [DllImport(Lib)] internal static extern void octocap_session_config_init(out SessionConfig cfg);
        [DllImport(Lib)] internal static extern Result octocap_session_create(ref SessionConfig cfg, CalibrationHandle calib, out SessionHandle session);
        [DllImport(Lib)] internal static extern void octocap_session_destroy(IntPtr session);
        [DllImport(Lib)] internal static extern Result octocap_session_solve_keypoints(SessionHandle s, Keypoint2D* keypoints, uint* peoplePerView, uint viewCount, long timestampUs);
        [DllImport(Lib)] internal static extern Result octocap_session_solve_images(SessionHandle s, Image* images, uint viewCount, long timestampUs);
        [DllImport(Lib)] internal static extern Result octocap_session_detections(SessionHandle s, uint view, Keypoint2D* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_session_detect_info(SessionHandle s, ref DetectInfo info);
        [DllImport(Lib)] internal static extern IntPtr octocap_onnxruntime_version();
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

        [DllImport(Lib)] internal static extern Result octocap_recording_open(string directory, Layout layout, out RecordingHandle rec);
        [DllImport(Lib)] internal static extern void octocap_recording_destroy(IntPtr rec);
        [DllImport(Lib)] internal static extern Result octocap_motion_open(string path, out MotionHandle motion);
        [DllImport(Lib)] internal static extern void octocap_motion_destroy(IntPtr motion);
        [DllImport(Lib)] internal static extern Result octocap_motion_info(MotionHandle motion, out uint frameCount, out double rateHz);
        [DllImport(Lib)] internal static extern Result octocap_motion_joints(MotionHandle motion, uint frame, Joint* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_motion_bones(MotionHandle motion, uint frame, CoordFrame coordFrame, BonePose* output, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_view_count(RecordingHandle rec, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_frame_count(RecordingHandle rec, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_recording_layout(RecordingHandle rec, out Layout layout);
        [DllImport(Lib)] internal static extern Result octocap_recording_read_frame(RecordingHandle rec, uint frame, Keypoint2D* keypoints, uint capacity, out uint keypointCount, uint* peoplePerView, uint viewCount);

        [DllImport(Lib)] internal static extern void octocap_subscriber_config_init(out SubscriberConfig cfg);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_create(ref SubscriberConfig cfg, out SubscriberHandle sub);
        [DllImport(Lib)] internal static extern void octocap_subscriber_destroy(IntPtr sub);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_take(SubscriberHandle sub, int timeoutMs);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_stream_info(SubscriberHandle sub, out StreamInfo info);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_frame_info(SubscriberHandle sub, out FrameInfo info);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_keypoints3d(SubscriberHandle sub, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_joints(SubscriberHandle sub, Joint* joints, uint capacity, out uint count);
        [DllImport(Lib)] internal static extern Result octocap_subscriber_get_bones(SubscriberHandle sub, CoordFrame frame, BonePose* bones, uint capacity, out uint count);

        internal static string Utf8(IntPtr p) => p == IntPtr.Zero ? null : Marshal.PtrToStringAnsi(p);
    }
}
