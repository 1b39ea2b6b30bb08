/**
 * @file octocap.h
 * @brief octocap: markerless multi-camera motion capture. The one public C ABI.
 *
 * octocap turns N calibrated camera views of a person into 3D joints and per-bone rotations that drive a
 * rigged avatar. A caller with its own 2D detector enters with 2D keypoints
 * (octocap_session_solve_keypoints); the result is queried per frame.
 *
 * @par Rules that hold for every function
 * - Every fallible call returns an ::octocap_result_t: ::OCTOCAP_OK (0) or a negative error code. The
 *   human-readable reason of the last failure on the calling thread is octocap_last_error().
 * - No C++ exception and no abort ever crosses this boundary.
 * - Handles are opaque and created/destroyed in pairs; every destroy function accepts NULL. Passing a
 *   destroyed handle is detected (::OCTOCAP_ERROR_INVALID_HANDLE) as long as its memory was not reused by a
 *   new handle of the same type; do not rely on it.
 * - Config structs start with `struct_size`; fill them with their `_init()` function first, so that fields
 *   added later get defaults and old callers keep working.
 * - Buffers are owned by the caller, with explicit capacities. Where the size is unknown, call with a NULL
 *   buffer to learn the count, then call again.
 * - Enumerations are plain `int32_t` typedefs with named constants, so their size is fixed in every
 *   language and an out-of-range value is an error code, not undefined behaviour.
 * - Per-frame structs are blittable (fixed-width integers and floats, no pointers, no bool) and can be mapped
 *   1:1 from C# with `[StructLayout(LayoutKind.Sequential)]`.
 *
 * @par Threads
 * One session (or calibration, recording, writer) is used by one thread at a time. Distinct handles may be
 * used from distinct threads in parallel. The library may run worker threads of its own inside a call.
 *
 * @par Conventions
 * Metres, seconds (timestamps in microseconds), radians. Pixel coordinates have their origin at the centre
 * of the top-left pixel (OpenCV's). Quaternions are (x, y, z, w), unit length. Joint positions are given in
 * the calibration's world frame. Bone rotations and the root are given in the rig frame: right-handed,
 * Y up (a Z-up calibration is turned with (x, y, z) -> (y, z, x), as Pose2Sim and OpenSim do), and can be
 * converted to Unity's or Godot's frame on request (::octocap_coord_frame_t).
 */
#ifndef OCTOCAP_OCTOCAP_H
#define OCTOCAP_OCTOCAP_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#  if defined(OCTOCAP_BUILDING_LIBRARY)
#    define OCTOCAP_API __declspec(dllexport)
#  else
#    define OCTOCAP_API __declspec(dllimport)
#  endif
#else
#  define OCTOCAP_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** ABI version, bumped on any incompatible change of this header. Compare with octocap_abi_version(). */
#define OCTOCAP_ABI_VERSION 1

/** Length of the fixed-size name fields, including the terminating NUL. */
#define OCTOCAP_NAME_CAPACITY 32

/* ------------------------------------------------------------------------------------------------------ */
/** @name Results, errors, logging, version */
/** @{ */

/** Result of every fallible call. */
typedef int32_t octocap_result_t;
/** Values of ::octocap_result_t. */
enum octocap_result_values {
  OCTOCAP_OK = 0,                        /**< Success. */
  OCTOCAP_ERROR_INVALID_ARGUMENT = -1,   /**< A NULL pointer, wrong size, NaN or out-of-range value. */
  OCTOCAP_ERROR_INVALID_HANDLE = -2,     /**< NULL, destroyed or wrong-type handle. */
  OCTOCAP_ERROR_STRUCT_SIZE = -3,        /**< A struct's struct_size is not one this library knows. */
  OCTOCAP_ERROR_IO = -4,                 /**< A file could not be opened, read or written. */
  OCTOCAP_ERROR_PARSE = -5,              /**< A file is malformed; the message names the file and the fault. */
  OCTOCAP_ERROR_BUFFER_TOO_SMALL = -6,   /**< The caller's buffer is too small; the count tells the size. */
  OCTOCAP_ERROR_CAMERA_MISMATCH = -7,    /**< The number of views differs from the calibration's cameras. */
  OCTOCAP_ERROR_NOT_ENOUGH_VIEWS = -8,   /**< Fewer views than the solve needs (sigma / min views). */
  OCTOCAP_ERROR_NO_RESULT = -9,          /**< Nothing solved yet (query before the first solve). */
  OCTOCAP_ERROR_UNSUPPORTED = -10,       /**< A feature this build does not include. */
  OCTOCAP_ERROR_INTERNAL = -99           /**< A bug: please report it with the message. */
};

/** Library version as "MAJOR.MINOR.PATCH". The string is static. */
OCTOCAP_API const char* octocap_version(void);
/** The ABI version the library was built with; equal to ::OCTOCAP_ABI_VERSION when header and library match. */
OCTOCAP_API uint32_t octocap_abi_version(void);
/** Static name of a result code, e.g. "OCTOCAP_ERROR_PARSE". */
OCTOCAP_API const char* octocap_result_name(octocap_result_t result);
/**
 * Message of the last failed call on this thread (empty string if none). Valid until the next failing
 * call on the same thread.
 */
OCTOCAP_API const char* octocap_last_error(void);

/** Log levels. */
typedef int32_t octocap_log_level_t;
/** Values of ::octocap_log_level_t. */
enum octocap_log_level_values {
  OCTOCAP_LOG_DEBUG = 0,
  OCTOCAP_LOG_INFO = 1,
  OCTOCAP_LOG_WARNING = 2,
  OCTOCAP_LOG_ERROR = 3
};

/** Log sink. May be called from any thread, including library worker threads; must not call back into octocap. */
typedef void (*octocap_log_callback_t)(octocap_log_level_t level, const char* message, void* user);

/**
 * Installs a process-wide log sink (NULL removes it) and the lowest level it receives. The library never
 * prints to stdout or stderr itself.
 */
OCTOCAP_API void octocap_set_log_callback(octocap_log_callback_t callback, octocap_log_level_t min_level, void* user);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Keypoint layouts and the skeleton (data that does not change per frame) */
/** @{ */

/** 2D keypoint layouts octocap reads. A layout is a table: names, order and mapping onto the skeleton. */
typedef int32_t octocap_layout_t;
/** Values of ::octocap_layout_t. */
enum octocap_layout_values {
  OCTOCAP_LAYOUT_AUTO = 0,      /**< Detect from the keypoint count (25 is taken as BODY_25). */
  OCTOCAP_LAYOUT_BODY_25 = 1,   /**< OpenPose BODY_25. */
  OCTOCAP_LAYOUT_BODY_25B = 2,  /**< OpenPose experimental BODY_25B (Pose2Sim's demo): COCO order + neck, head, feet. */
  OCTOCAP_LAYOUT_COCO_17 = 3,   /**< COCO-17 (MoveNet, RTMPose, YOLO-pose). */
  OCTOCAP_LAYOUT_HALPE_26 = 4   /**< HALPE-26 (AlphaPose, RTMPose body7 halpe26). */
};

/** Number of keypoints of a layout (0 for an unknown or AUTO layout). */
OCTOCAP_API uint32_t octocap_layout_keypoint_count(octocap_layout_t layout);
/** Static name of a layout ("BODY_25B") or NULL. */
OCTOCAP_API const char* octocap_layout_name(octocap_layout_t layout);
/** Parses a layout name (case-insensitive, "BODY_25B", "COCO_17", "COCO", ...). */
OCTOCAP_API octocap_result_t octocap_layout_from_name(const char* name, octocap_layout_t* out);
/** Static name of keypoint `index` of `layout` ("RShoulder"), or NULL when out of range. */
OCTOCAP_API const char* octocap_layout_keypoint_name(octocap_layout_t layout, uint32_t index);

/** The paper's skeleton: 14 joints plus a root at the hip centre. */
typedef int32_t octocap_joint_id_t;
/** Values of ::octocap_joint_id_t. */
enum octocap_joint_id_values {
  OCTOCAP_JOINT_HEAD = 0,
  OCTOCAP_JOINT_NECK = 1,
  OCTOCAP_JOINT_R_SHOULDER = 2,
  OCTOCAP_JOINT_R_ELBOW = 3,
  OCTOCAP_JOINT_R_HAND = 4,
  OCTOCAP_JOINT_L_SHOULDER = 5,
  OCTOCAP_JOINT_L_ELBOW = 6,
  OCTOCAP_JOINT_L_HAND = 7,
  OCTOCAP_JOINT_R_HIP = 8,
  OCTOCAP_JOINT_R_KNEE = 9,
  OCTOCAP_JOINT_R_FOOT = 10,
  OCTOCAP_JOINT_L_HIP = 11,
  OCTOCAP_JOINT_L_KNEE = 12,
  OCTOCAP_JOINT_L_FOOT = 13,
  OCTOCAP_JOINT_ROOT = 14,
  OCTOCAP_JOINT_COUNT = 15
};

/**
 * Bones of the rig. ROOT carries the global orientation of the pelvis; every other bone goes from a parent
 * joint to a child joint and rotates relative to its parent bone.
 */
typedef int32_t octocap_bone_id_t;
/** Values of ::octocap_bone_id_t. */
enum octocap_bone_id_values {
  OCTOCAP_BONE_ROOT = 0,
  OCTOCAP_BONE_TORSO = 1,
  OCTOCAP_BONE_HEAD = 2,
  OCTOCAP_BONE_R_SHOULDER = 3,
  OCTOCAP_BONE_R_UPPER_ARM = 4,
  OCTOCAP_BONE_R_LOWER_ARM = 5,
  OCTOCAP_BONE_L_SHOULDER = 6,
  OCTOCAP_BONE_L_UPPER_ARM = 7,
  OCTOCAP_BONE_L_LOWER_ARM = 8,
  OCTOCAP_BONE_R_UPPER_LEG = 9,
  OCTOCAP_BONE_R_LOWER_LEG = 10,
  OCTOCAP_BONE_L_UPPER_LEG = 11,
  OCTOCAP_BONE_L_LOWER_LEG = 12,
  OCTOCAP_BONE_COUNT = 13
};

/** Static name of a skeleton joint ("r_elbow") or NULL. */
OCTOCAP_API const char* octocap_joint_name(uint32_t joint);

/** Static description of one bone of the rig (the skeleton definition). */
typedef struct octocap_bone_info_t {
  char name[OCTOCAP_NAME_CAPACITY]; /**< "r_upper_arm". */
  int32_t parent_bone;               /**< Parent bone index, -1 for ROOT. */
  int32_t head_joint;                /**< Joint the bone starts at (::octocap_joint_id_t). */
  int32_t tail_joint;                /**< Joint the bone ends at (::octocap_joint_id_t). */
  float rest_direction[3];           /**< Unit direction head->tail in the T-pose template, rig frame (Y up, facing +Z). */
} octocap_bone_info_t;

/** Fills `out` with the definition of bone `bone`. */
OCTOCAP_API octocap_result_t octocap_bone_info(uint32_t bone, octocap_bone_info_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Calibration */
/** @{ */

/** Opaque calibration: a set of cameras (intrinsics, distortion, pose). */
typedef struct octocap_calibration_t octocap_calibration_t;

/** One camera, as stored in the anipose/Pose2Sim calibration TOML. */
typedef struct octocap_camera_t {
  char name[OCTOCAP_NAME_CAPACITY]; /**< Camera name (truncated to fit). */
  uint32_t width;                   /**< Image width, pixels. */
  uint32_t height;                  /**< Image height, pixels. */
  double matrix[9];                 /**< Intrinsic matrix K, row-major. */
  double distortion[5];             /**< OpenCV k1, k2, p1, p2, k3 (pinhole) or k1..k4 (fisheye, last unused). */
  uint32_t fisheye;                 /**< 1 for OpenCV's fisheye model, else 0. */
  double rotation[3];               /**< World->camera rotation as a Rodrigues vector. */
  double translation[3];            /**< World->camera translation, metres. */
} octocap_camera_t;

/** Loads an anipose/Pose2Sim calibration TOML (`[cam_N]` tables, in file order). */
OCTOCAP_API octocap_result_t octocap_calibration_load(const char* path, octocap_calibration_t** out);
/** Creates a calibration from `count` cameras. */
OCTOCAP_API octocap_result_t octocap_calibration_create(const octocap_camera_t* cameras, uint32_t count,
                                                        octocap_calibration_t** out);
/** Writes the calibration as anipose/Pose2Sim TOML. */
OCTOCAP_API octocap_result_t octocap_calibration_save(const octocap_calibration_t* calib, const char* path);
/** Number of cameras. */
OCTOCAP_API octocap_result_t octocap_calibration_camera_count(const octocap_calibration_t* calib, uint32_t* out);
/** Copies camera `index`. */
OCTOCAP_API octocap_result_t octocap_calibration_get_camera(const octocap_calibration_t* calib, uint32_t index,
                                                            octocap_camera_t* out);
/** Projects a world point (metres) into camera `index`, with distortion; pixel coordinates out. */
OCTOCAP_API octocap_result_t octocap_calibration_project(const octocap_calibration_t* calib, uint32_t index,
                                                         const double world[3], double pixel_out[2]);
/** Destroys a calibration; NULL is accepted. Sessions created from it keep their own copy. */
OCTOCAP_API void octocap_calibration_destroy(octocap_calibration_t* calib);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Session: per-frame solve */
/** @{ */

/** Opaque session: solver state for one capture (previous frame, filter, person tracking). */
typedef struct octocap_session_t octocap_session_t;

/** 3D method. */
typedef int32_t octocap_method_t;
/** Values of ::octocap_method_t. */
enum octocap_method_values {
  OCTOCAP_METHOD_SUBDIVISION = 0,   /**< The paper's iterative space subdivision. */
  OCTOCAP_METHOD_TRIANGULATION = 1, /**< Confidence-weighted DLT with outlier-view rejection. */
  OCTOCAP_METHOD_AUTO = 2           /**< Subdivision with 5 or more cameras, triangulation with fewer: what
                                         measured more accurate for each (README, "Choosing the defaults"). */
};

/** Temporal filter. */
typedef int32_t octocap_filter_t;
/** Values of ::octocap_filter_t. */
enum octocap_filter_values {
  OCTOCAP_FILTER_NONE = 0,
  OCTOCAP_FILTER_ONE_EURO = 1  /**< Causal One Euro filter: smooth when slow, no lag when fast. */
};

/** QoS profile of a skeleton stream; publisher and subscriber must use the same one. */
typedef int32_t octocap_stream_qos_t;
/** Values of ::octocap_stream_qos_t. */
enum octocap_stream_qos_t_values {
  OCTOCAP_QOS_LIVE = 0,   /**< BEST_EFFORT, VOLATILE, KEEP_LAST 1: the newest pose, never an old one late (engines). */
  OCTOCAP_QOS_RECORD = 1  /**< RELIABLE, TRANSIENT_LOCAL, KEEP_LAST depth: every frame; late joiners get the last
                               `depth` poses (recorders). */
};

/** Up axis of the calibration's world frame. */
typedef int32_t octocap_up_axis_t;
/** Values of ::octocap_up_axis_t. */
enum octocap_up_axis_values {
  OCTOCAP_UP_Y = 0,    /**< Y up (octocap's convention). */
  OCTOCAP_UP_Z = 1,    /**< Z up (Qualisys, Pose2Sim calibrations, most lab systems). */
  OCTOCAP_UP_AUTO = 2  /**< Decide from the cameras: upright cameras' image "down" axes point to world down. */
};

/** Session configuration. Fill with octocap_session_config_init() first. */
typedef struct octocap_session_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_session_config_t). */
  octocap_layout_t layout;       /**< Keypoint layout of the 2D input (AUTO is not allowed here). Default BODY_25. */
  octocap_method_t method;       /**< Default AUTO; see octocap_session_method() for the resolved one. */
  octocap_filter_t filter;       /**< Default ONE_EURO. */
  octocap_up_axis_t up_axis;     /**< Default AUTO; see octocap_session_up_axis() for the resolved one. */
  uint32_t sigma;                /**< Views a cube must be supported by. 0 = camera count - 1 (min 2). Clamped to the views that saw the joint, never below min_views. */
  uint32_t min_views;            /**< Fewest views a joint is solved from. Default 2. */
  float delta_m;                 /**< Smallest cube edge, metres. Default 0.01. */
  float pixel_tolerance;         /**< Subdivision: a detection within this many pixels of a cube's projection supports it. Default 4. */
  uint32_t max_candidates;       /**< Subdivision: candidate cubes kept per level, best supported and closest to the rays first (bounds the cost). Default 8. */
  float min_confidence;          /**< 2D keypoints below this confidence are treated as missing. Default 0.3. */
  float outlier_threshold_px;    /**< A view farther than this from the joint's reprojection is rejected. Default 15. */
  float volume_min[3];           /**< Capture volume (world, metres). When min == max, it is derived from the calibration. */
  float volume_max[3];
  float filter_min_cutoff_hz;    /**< One Euro min cutoff. Default 1.5. */
  float filter_beta;             /**< One Euro speed coefficient (1/m). Default 20 (see README for the measurements). */
  uint32_t worker_threads;       /**< Threads used across joints; 0 = hardware concurrency, 1 = none. */
  /* Added in 0.2 (a caller compiled against 0.1 passes the smaller struct_size and gets the defaults). */
  int64_t first_frame_index;     /**< Frame numbers start here (default 0): a resumed take keeps its numbering. */
  uint32_t stream_enable;        /**< 1: publish every solved frame over DDS (see "Streaming"). Default 0. */
  uint32_t stream_domain_id;     /**< DDS domain. Default 0. */
  octocap_stream_qos_t stream_qos; /**< Default ::OCTOCAP_QOS_LIVE. */
  uint32_t stream_history_depth; /**< Poses a RECORD stream keeps for late joiners. Default 256. */
  uint32_t stream_source_id;     /**< Identifies this rig on a shared topic (the DDS key). Default 1. */
  char stream_topic[OCTOCAP_NAME_CAPACITY]; /**< Topic base name, "<name>_pose" and "<name>_definition". Default "octocap". */
} octocap_session_config_t;

/** Fills `cfg` with defaults and sets its struct_size. */
OCTOCAP_API void octocap_session_config_init(octocap_session_config_t* cfg);

/**
 * Creates a session. `calib` is copied; it may be destroyed afterwards. Fails on a config with a wrong
 * struct_size, NaN or out-of-range values, or a calibration with fewer than 2 cameras.
 */
OCTOCAP_API octocap_result_t octocap_session_create(const octocap_session_config_t* cfg,
                                                    const octocap_calibration_t* calib,
                                                    octocap_session_t** out);
/** Destroys a session; NULL is accepted. */
OCTOCAP_API void octocap_session_destroy(octocap_session_t* session);

/** One 2D keypoint in pixels. confidence <= 0 (or x, y = 0, 0 as OpenPose writes it) means "not detected". */
typedef struct octocap_keypoint2d_t {
  float x;
  float y;
  float confidence;
} octocap_keypoint2d_t;

/**
 * Solves one frame from 2D keypoints.
 *
 * @param keypoints  Flat array: for view 0 its people one after the other, then view 1, ... Each person is
 *                   octocap_layout_keypoint_count(layout) keypoints in the layout's order.
 * @param people_per_view  view_count counts (0 = nobody detected in that view), or NULL for exactly one
 *                   person per view. With several people in a view, the session picks the one who agrees
 *                   with the other views and with the previous frame.
 * @param view_count Must equal the calibration's camera count (cameras in calibration order).
 * @param timestamp_us  Frame time in microseconds; must increase for the filter to work.
 * @return OCTOCAP_OK also when some joints could not be solved (they are reported missing);
 *         OCTOCAP_ERROR_NOT_ENOUGH_VIEWS when fewer than min_views views hold a person (the frame is
 *         then empty and the session stays usable).
 */
OCTOCAP_API octocap_result_t octocap_session_solve_keypoints(octocap_session_t* session,
                                                             const octocap_keypoint2d_t* keypoints,
                                                             const uint32_t* people_per_view,
                                                             uint32_t view_count, int64_t timestamp_us);

/** The 3D method in use (AUTO resolved at creation). */
OCTOCAP_API octocap_result_t octocap_session_method(const octocap_session_t* session, octocap_method_t* out);

/** The up axis in use (AUTO resolved to Y or Z at creation). */
OCTOCAP_API octocap_result_t octocap_session_up_axis(const octocap_session_t* session, octocap_up_axis_t* out);

/** Blocks until every frame this session published has been handed to DDS (no-op when not streaming). */
OCTOCAP_API octocap_result_t octocap_session_flush_stream(octocap_session_t* session);

/** Resets temporal state (filter, person tracking), e.g. between takes. */
OCTOCAP_API octocap_result_t octocap_session_reset(octocap_session_t* session);

/** A solved 3D point (a layout keypoint or a skeleton joint). */
typedef struct octocap_joint_t {
  float position[3];           /**< World frame of the calibration, metres. Zero when missing. */
  float confidence;            /**< Mean 2D confidence of the supporting views; 0 when missing. */
  float reprojection_error_px; /**< Mean distance (px) between the reprojection of the solved point (before the
                                    temporal filter) and the supporting detections. */
  uint32_t views_used;         /**< Number of views that supported the point. */
  uint32_t valid;              /**< 1 when solved, 0 when missing (never a guess). */
} octocap_joint_t;

/** Frame-level summary of the last solve. */
typedef struct octocap_frame_info_t {
  int64_t frame_index;          /**< 0 for the first solved frame of the session. */
  int64_t timestamp_us;
  uint32_t keypoints_solved;    /**< Layout keypoints with valid = 1. */
  uint32_t keypoints_total;
  float mean_reprojection_error_px; /**< Mean over solved keypoints. */
  uint32_t views_with_person;   /**< Views in which a person was selected. */
  float solve_ms;               /**< Wall time of the 3D solve of this frame. */
} octocap_frame_info_t;

/** Summary of the last frame (::OCTOCAP_ERROR_NO_RESULT before the first solve). */
OCTOCAP_API octocap_result_t octocap_session_get_frame_info(const octocap_session_t* session,
                                                            octocap_frame_info_t* out);

/** The 3D layout keypoints of the last frame (capacity >= layout keypoint count; NULL out to query count). */
OCTOCAP_API octocap_result_t octocap_session_get_keypoints3d(const octocap_session_t* session, octocap_joint_t* out,
                                                             uint32_t capacity, uint32_t* count);

/** The ::OCTOCAP_JOINT_COUNT skeleton joints of the last frame (NULL out to query the count). */
OCTOCAP_API octocap_result_t octocap_session_get_joints(const octocap_session_t* session, octocap_joint_t* out,
                                                        uint32_t capacity, uint32_t* count);

/** Index of the person selected in each view for the last frame (-1 = none). */
OCTOCAP_API octocap_result_t octocap_session_get_selected_people(const octocap_session_t* session, int32_t* out,
                                                                 uint32_t capacity, uint32_t* count);

/** Coordinate frame for bone queries. */
typedef int32_t octocap_coord_frame_t;
/** Values of ::octocap_coord_frame_t. */
enum octocap_coord_frame_values {
  OCTOCAP_FRAME_RIG = 0,    /**< Right-handed, Y up, character faces +Z in the T-pose. */
  OCTOCAP_FRAME_UNITY = 1,  /**< Left-handed, Y up, +Z forward (X mirrored). */
  OCTOCAP_FRAME_GODOT = 2   /**< Right-handed, Y up, character faces -Z (turned 180 degrees about Y). */
};

/** Quaternion (x, y, z, w). */
typedef struct octocap_quat_t {
  float x, y, z, w;
} octocap_quat_t;

/** The pose of one bone in the last frame. */
typedef struct octocap_bone_pose_t {
  octocap_quat_t local_rotation;  /**< Rotation relative to the parent bone, from the T-pose (identity = T-pose). */
  octocap_quat_t global_rotation; /**< Rotation in the chosen frame, from the T-pose. */
  float head_position[3];         /**< Where the bone starts, chosen frame, metres. */
  float length_m;                 /**< Measured length this frame. */
  uint32_t valid;                 /**< 0 when a joint of the bone is missing; rotations are then identity. */
} octocap_bone_pose_t;

/** The ::OCTOCAP_BONE_COUNT bone poses of the last frame, converted to `frame` (NULL out to query the count). */
OCTOCAP_API octocap_result_t octocap_session_get_bones(const octocap_session_t* session, octocap_coord_frame_t frame,
                                                       octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count);

/** Local rotation of one bone (convenience over octocap_session_get_bones). */
OCTOCAP_API octocap_result_t octocap_session_get_bone_rotation(const octocap_session_t* session, uint32_t bone,
                                                               octocap_coord_frame_t frame, octocap_quat_t* out);

/**
 * Counter that changes whenever the skeleton definition changes (layout, bone table). A consumer caches the
 * definition and re-reads it when this changes.
 */
OCTOCAP_API octocap_result_t octocap_session_definition_counter(const octocap_session_t* session, uint32_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Streaming: receiving skeletons over Cyclone DDS
 *
 * A session with `stream_enable` publishes every frame on two topics: "<topic>_definition" (the skeleton
 * definition: layout, keypoint and joint names, bones; reliable, transient-local, so a late joiner always has
 * it) and "<topic>_pose" (per frame). Publishing never blocks the solve: frames go to a queue that a
 * library thread writes; when it is full the oldest frame is dropped. A subscriber, in this process or on
 * another machine, reads the same queries as a local session. Cyclone is configured as usual through the
 * CYCLONEDDS_URI environment variable (network interface, multicast, peers).
 */
/** @{ */

/** Opaque stream subscriber. */
typedef struct octocap_subscriber_t octocap_subscriber_t;

/** Subscriber configuration. Fill with octocap_subscriber_config_init() first. */
typedef struct octocap_subscriber_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_subscriber_config_t). */
  uint32_t domain_id;            /**< DDS domain. Default 0. */
  octocap_stream_qos_t qos;      /**< Must match the publisher's. Default ::OCTOCAP_QOS_LIVE. */
  uint32_t history_depth;        /**< RECORD: poses kept for this reader. Default 256. */
  uint32_t source_id;            /**< Only this source; 0 = any. Default 0. */
  char topic[OCTOCAP_NAME_CAPACITY]; /**< Default "octocap". */
} octocap_subscriber_config_t;

/** Counters of a subscription. */
typedef struct octocap_stream_info_t {
  uint64_t frames_received;      /**< Poses taken. */
  uint64_t frames_lost;          /**< Frame numbers skipped, summed over the stream. */
  uint64_t last_gap;             /**< Frames missing right before the current one (0 = none). */
  uint64_t restarts;             /**< Times the frame numbers went backwards: the publisher restarted. */
  uint64_t rejected;             /**< Samples refused (other wire version, wrong sizes, NaN); each is logged. */
  uint32_t source_id;            /**< Source of the current frame. */
  uint32_t definition_counter;   /**< Change counter of the skeleton definition received. */
  octocap_layout_t layout;       /**< Keypoint layout of the stream. */
  uint32_t has_definition;       /**< 1 once the skeleton definition has arrived. */
} octocap_stream_info_t;

/** Fills `cfg` with defaults and sets its struct_size. */
OCTOCAP_API void octocap_subscriber_config_init(octocap_subscriber_config_t* cfg);
/** Joins a stream. */
OCTOCAP_API octocap_result_t octocap_subscriber_create(const octocap_subscriber_config_t* cfg,
                                                       octocap_subscriber_t** out);
/** Leaves the stream; NULL is accepted. */
OCTOCAP_API void octocap_subscriber_destroy(octocap_subscriber_t* sub);
/**
 * Takes the next pose in arrival order, waiting up to `timeout_ms` (0: do not wait), and makes it the current
 * frame for the queries below. ::OCTOCAP_ERROR_NO_RESULT when none arrived in time (the previous frame stays).
 */
OCTOCAP_API octocap_result_t octocap_subscriber_take(octocap_subscriber_t* sub, int32_t timeout_ms);
/** Counters: frames received and lost, publisher restarts, rejected samples. */
OCTOCAP_API octocap_result_t octocap_subscriber_get_stream_info(const octocap_subscriber_t* sub,
                                                                octocap_stream_info_t* out);
/** As octocap_session_get_frame_info(), for the current received frame (solve_ms is 0). */
OCTOCAP_API octocap_result_t octocap_subscriber_get_frame_info(const octocap_subscriber_t* sub,
                                                               octocap_frame_info_t* out);
/** As octocap_session_get_keypoints3d(), for the current received frame. */
OCTOCAP_API octocap_result_t octocap_subscriber_get_keypoints3d(const octocap_subscriber_t* sub, octocap_joint_t* out,
                                                                uint32_t capacity, uint32_t* count);
/** As octocap_session_get_joints(), for the current received frame. */
OCTOCAP_API octocap_result_t octocap_subscriber_get_joints(const octocap_subscriber_t* sub, octocap_joint_t* out,
                                                           uint32_t capacity, uint32_t* count);
/** As octocap_session_get_bones(), for the current received frame. */
OCTOCAP_API octocap_result_t octocap_subscriber_get_bones(const octocap_subscriber_t* sub, octocap_coord_frame_t frame,
                                                          octocap_bone_pose_t* out, uint32_t capacity,
                                                          uint32_t* count);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Recordings on disk: OpenPose JSON folders (Pose2Sim layout) */
/** @{ */

/** Opaque OpenPose JSON recording: one sub-folder per camera (sorted by name), one file per frame (sorted). */
typedef struct octocap_recording_t octocap_recording_t;

/**
 * Opens a folder of per-camera OpenPose JSON folders. Files are parsed lazily per frame; the folder
 * structure is checked here. `layout` AUTO detects it from the first file's keypoint count.
 */
OCTOCAP_API octocap_result_t octocap_recording_open(const char* directory, octocap_layout_t layout,
                                                    octocap_recording_t** out);
/** Destroys a recording; NULL is accepted. */
OCTOCAP_API void octocap_recording_destroy(octocap_recording_t* rec);
/** Number of views (camera folders). */
OCTOCAP_API octocap_result_t octocap_recording_view_count(const octocap_recording_t* rec, uint32_t* out);
/** Number of frames (the smallest file count of the camera folders). */
OCTOCAP_API octocap_result_t octocap_recording_frame_count(const octocap_recording_t* rec, uint32_t* out);
/** The layout in use (resolved when AUTO was given). */
OCTOCAP_API octocap_result_t octocap_recording_layout(const octocap_recording_t* rec, octocap_layout_t* out);
/** Name of camera folder `view` (e.g. "cam1_json"), copied into `out` (capacity bytes incl. NUL). */
OCTOCAP_API octocap_result_t octocap_recording_view_name(const octocap_recording_t* rec, uint32_t view, char* out,
                                                         uint32_t capacity);

/**
 * Reads frame `frame`: fills people_per_view (view_count entries) and the flat keypoints array in the
 * layout of octocap_session_solve_keypoints. With keypoints == NULL only `keypoint_count` (total keypoints
 * needed) is written. Returns ::OCTOCAP_ERROR_BUFFER_TOO_SMALL when `capacity` is short.
 */
OCTOCAP_API octocap_result_t octocap_recording_read_frame(octocap_recording_t* rec, uint32_t frame,
                                                          octocap_keypoint2d_t* keypoints, uint32_t capacity,
                                                          uint32_t* keypoint_count, uint32_t* people_per_view,
                                                          uint32_t view_count);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Motion files: TRC (OpenSim/Pose2Sim) and CSV */
/** @{ */

/** Opaque writer of 3D keypoints, one row per frame. */
typedef struct octocap_motion_writer_t octocap_motion_writer_t;

/** File formats of ::octocap_motion_writer_t. */
typedef int32_t octocap_motion_format_t;
/** Values of ::octocap_motion_format_t. */
enum octocap_motion_format_values {
  OCTOCAP_MOTION_TRC = 0, /**< OpenSim TRC, Y up (Z-up worlds are turned as Pose2Sim does), metres. */
  OCTOCAP_MOTION_CSV = 1  /**< `frame,NAME_x,NAME_y,NAME_z,...`, calibration world frame, empty cells when missing. */
};

/**
 * Creates a writer. The file is written on octocap_motion_writer_close() (TRC needs the frame count in its
 * header). `rate_hz` is the frame rate written to TRC.
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_create(const char* path, octocap_motion_format_t format,
                                                          octocap_layout_t layout, octocap_up_axis_t up_axis,
                                                          double rate_hz, octocap_motion_writer_t** out);
/** Appends the last frame's layout keypoints of `session`. */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_frame(octocap_motion_writer_t* writer,
                                                             const octocap_session_t* session);
/** Appends `count` 3D keypoints (layout order, e.g. from octocap_subscriber_get_keypoints3d()). */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_keypoints(octocap_motion_writer_t* writer,
                                                                 const octocap_joint_t* keypoints, uint32_t count);
/** Appends an empty frame (nothing solved). */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_empty_frame(octocap_motion_writer_t* writer);
/** Writes the file and destroys the writer (also on failure). NULL is accepted. */
OCTOCAP_API octocap_result_t octocap_motion_writer_close(octocap_motion_writer_t* writer);

/** @} */

#ifdef __cplusplus
}
#endif

#endif /* OCTOCAP_OCTOCAP_H */
