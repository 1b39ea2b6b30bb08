/**
 * @file octocap.h
 * @brief octocap: markerless multi-camera motion capture. The one public C ABI (C99).
 *
 * octocap turns N calibrated camera views of people into 3D joints and per-bone rotations that drive rigged
 * avatars. Read this header top to bottom: versions and results, the skeleton definition, calibrations, frames
 * (the one result type), detection, the session that solves frames, streaming, files.
 *
 * A minimal program: load a calibration, create a session, give it each frame's 2D keypoints (your detector's)
 * or camera images (octocap's detector), read the frame:
 * @code
 * octocap_calibration_t* calib;  octocap_calibration_load("calibration.toml", &calib);
 * octocap_session_config_t cfg;  octocap_session_config_init(&cfg);  cfg.layout = OCTOCAP_LAYOUT_COCO_17;
 * octocap_session_t* s;          octocap_session_create(&cfg, calib, &s);
 * if (octocap_session_solve_keypoints(s, keypoints, NULL, views, t_us) == OCTOCAP_OK) {
 *   octocap_frame_t* f;          octocap_session_get_frame(s, &f);
 *   octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT]; uint32_t n;
 *   octocap_frame_get_bones(f, 0, OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n);
 *   octocap_frame_release(f);
 * }
 * @endcode
 *
 * @par Rules that hold for every function
 * - Every fallible call returns an ::octocap_result_t: ::OCTOCAP_OK (0), a positive status for a normal outcome
 *   that produced nothing (::OCTOCAP_STATUS_NO_PERSON, ::OCTOCAP_STATUS_TIMEOUT), or a negative error code. Test
 *   errors with OCTOCAP_FAILED(). The reason of the last error on the calling thread is octocap_last_error().
 * - Each function lists, as `@retval`, every result it returns. One is left out of the lists because any fallible
 *   call can return it: ::OCTOCAP_ERROR_INTERNAL, an exception the library did not expect, caught at the boundary
 *   (a bug: report it with octocap_last_error()). ::OCTOCAP_ERROR_OUT_OF_MEMORY is listed where a call allocates.
 * - No C++ exception and no abort ever crosses this boundary.
 * - Handles are opaque and created/destroyed in pairs; every destroy/release function accepts NULL. Passing a
 *   destroyed handle is detected (::OCTOCAP_ERROR_INVALID_HANDLE) as long as its memory was not reused by a
 *   new handle of the same type; do not rely on it.
 * - Buffers are owned by the caller, with explicit capacities. Where the size is unknown, call with a NULL
 *   buffer to learn the count, then call again. Strings are UTF-8 and NUL-terminated.
 * - Enumerations are plain `int32_t` typedefs with named constants, so their size is fixed in every
 *   language and an out-of-range value is an error code, not undefined behaviour.
 * - Per-frame structs are blittable (fixed-width integers and floats, no pointers, no bool) and can be mapped
 *   1:1 from C# with `[StructLayout(LayoutKind.Sequential)]`.
 *
 * @par Versions and compatibility
 * The library keeps working with programs built against any earlier header of the same major version (and
 * against every 0.x header): functions are never removed (superseded ones move to the "Deprecated" group) and
 * structs only grow at their end. Config structs start with `struct_size`; their `_init()` functions are inline
 * in this header, so they write exactly the struct the program was compiled with, and the library accepts every
 * size a released header had (fields a program does not have take their defaults). Output structs that start with
 * `struct_size` are filled up to the size the caller set. The soname (liboctocap.so.0) changes only if that promise
 * is ever broken. A program checks at start that the library is not older than its header:
 * `octocap_version_number() >= OCTOCAP_VERSION_NUMBER` and the same major version.
 *
 * Every declaration says with `@since` the header version that brought it (the released headers are kept in
 * tests/abi/headers/, and the ABI tests build programs against each); a struct field or constant newer than its
 * type says so itself. A program that must run on an older library calls only what that version has.
 *
 * @par Threads
 * One session (or calibration, subscriber, recording, writer, motion) is used by one thread at a time. Distinct
 * handles may be used from distinct threads in parallel. Frames are immutable and may be read from any thread.
 * The library may run worker threads of its own inside a call, and a streaming session runs one publisher thread.
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

/**
 * @def OCTOCAP_API
 * Marks a function the library exports: default visibility (the library is built with hidden visibility, so only
 * these names are its ABI), `__declspec(dllexport)` / `dllimport` on Windows.
 * @since 0.1
 */
#if defined(_WIN32)
#  if defined(OCTOCAP_BUILDING_LIBRARY)
#    define OCTOCAP_API __declspec(dllexport)
#  else
#    define OCTOCAP_API __declspec(dllimport)
#  endif
#else
#  define OCTOCAP_API __attribute__((visibility("default")))
#endif

/* The deprecated group (0.x's per-source queries) warns where it is called, so that code moves to frames before the
 * day the group goes. A program that keeps calling it on purpose (a test of the old path) defines
 * OCTOCAP_NO_DEPRECATION_WARNINGS before the include. */
/**
 * @def OCTOCAP_DEPRECATED(message)
 * Marks a declaration of the deprecated group: the compiler warns where it is called, with `message` naming what
 * replaces it. Defining OCTOCAP_NO_DEPRECATION_WARNINGS before the include silences it (a test of the old path).
 * @param message What to call instead, shown in the compiler's warning.
 * @since 1.9
 */
#if defined(OCTOCAP_NO_DEPRECATION_WARNINGS) || defined(OCTOCAP_BUILDING_LIBRARY)
#  define OCTOCAP_DEPRECATED(message)
#elif defined(__GNUC__) || defined(__clang__)
#  define OCTOCAP_DEPRECATED(message) __attribute__((deprecated(message)))
#elif defined(_MSC_VER)
#  define OCTOCAP_DEPRECATED(message) __declspec(deprecated(message))
#else
#  define OCTOCAP_DEPRECATED(message)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------------------------------------ */
/** @name Versions, results, errors, logging */
/** @{ */

/* Version of this header (the library's own is octocap_version_number()). One line each, nothing after the number:
 * CMakeLists.txt and scripts/header_version.py read them as they are. */
/** Major version of this header: a program built against an earlier header of the same major runs on this one.
 *  @since 1.0 */
#define OCTOCAP_VERSION_MAJOR 1
/** Minor version of this header: grows with each release that adds to the API. @since 1.0 */
#define OCTOCAP_VERSION_MINOR 13
/** Patch version of this header: a release of fixes that leaves the API as it was. @since 1.0 */
#define OCTOCAP_VERSION_PATCH 0
/** MAJOR * 10000 + MINOR * 100 + PATCH: 10000 for 1.0.0. @since 1.0 */
#define OCTOCAP_VERSION_NUMBER (OCTOCAP_VERSION_MAJOR * 10000 + OCTOCAP_VERSION_MINOR * 100 + OCTOCAP_VERSION_PATCH)
/** ABI line: bumped only by an incompatible change (none so far). Compare with octocap_abi_version(). @since 0.1 */
#define OCTOCAP_ABI_VERSION 1

/** The port VMC protocol receivers (Virtual Motion Capture, VSeeFace, EVMC4U) listen on by default. @since 0.2 */
#define OCTOCAP_VMC_DEFAULT_PORT 39539

/** Length of the fixed-size name fields, including the terminating NUL. @since 0.1 */
#define OCTOCAP_NAME_CAPACITY 32
/** Capacity of the error texts of status structs, NUL included; longer ones are cut. @since 1.6 */
#define OCTOCAP_ERROR_TEXT_CAPACITY 256

/** Result of every fallible call. @since 0.1 */
typedef int32_t octocap_result_t;
/** Values of ::octocap_result_t: 0 success, positive normal outcomes, negative errors. @since 0.1 */
enum octocap_result_values {
  OCTOCAP_OK = 0,                        /**< Success. */
  OCTOCAP_STATUS_NO_PERSON = 1,          /**< Not an error: the frame was taken, but too few views saw a person to
                                              solve one (the frame has no person; the session goes on).
                                              @since 1.0 */
  OCTOCAP_STATUS_TIMEOUT = 2,            /**< Not an error: nothing arrived before the timeout. @since 1.0 */
  OCTOCAP_ERROR_INVALID_ARGUMENT = -1,   /**< A NULL pointer, wrong size, NaN or out-of-range value. */
  OCTOCAP_ERROR_INVALID_HANDLE = -2,     /**< NULL, destroyed or wrong-type handle. */
  OCTOCAP_ERROR_STRUCT_SIZE = -3,        /**< A struct's struct_size is not one any version of this header had. */
  OCTOCAP_ERROR_IO = -4,                 /**< A file could not be opened, read or written. */
  OCTOCAP_ERROR_PARSE = -5,              /**< A file is malformed; the message names the file and the fault. */
  OCTOCAP_ERROR_BUFFER_TOO_SMALL = -6,   /**< The caller's buffer is too small; the count tells the size. */
  OCTOCAP_ERROR_CAMERA_MISMATCH = -7,    /**< The number of views differs from the calibration's cameras. */
  OCTOCAP_ERROR_NOT_ENOUGH_VIEWS = -8,   /**< Too few cameras for the task: a session over fewer than 2, a
                                              calibration or sync in which a camera never sees enough with the
                                              others. Solves no longer return it (they did in 0.x): a frame that
                                              too few views saw is ::OCTOCAP_STATUS_NO_PERSON. */
  OCTOCAP_ERROR_NO_RESULT = -9,          /**< Nothing to read yet (a query before the first solve). */
  OCTOCAP_ERROR_UNSUPPORTED = -10,       /**< A feature this build does not include. */
  OCTOCAP_ERROR_OUT_OF_MEMORY = -11,     /**< An allocation failed; the handle involved stays usable. @since 1.0 */
  OCTOCAP_ERROR_INTERNAL = -99           /**< A bug: please report it with the message. */
};

/**
 * True for an error (negative result), false for ::OCTOCAP_OK and the positive statuses.
 * @param result An ::octocap_result_t.
 * @since 1.0
 */
#define OCTOCAP_FAILED(result) ((result) < 0)

/**
 * Library version as "MAJOR.MINOR.PATCH".
 * @return A static string.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_version(void);
/**
 * Library version as MAJOR * 10000 + MINOR * 100 + PATCH (compare with ::OCTOCAP_VERSION_NUMBER).
 * @return The version number of the library in use (not of this header).
 * @since 1.0
 */
OCTOCAP_API uint32_t octocap_version_number(void);
/**
 * The ABI line of the library; equal to ::OCTOCAP_ABI_VERSION for every library this header works with.
 * @return The library's ABI line.
 * @since 0.1
 */
OCTOCAP_API uint32_t octocap_abi_version(void);
/**
 * Static name of a result code, such as "OCTOCAP_ERROR_PARSE".
 * @param[in] result Any value; one that is no ::octocap_result_values gives "OCTOCAP_UNKNOWN_RESULT".
 * @return A static string, never NULL.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_result_name(octocap_result_t result);
/**
 * Message of the last failed call on this thread (empty string if none). Valid until the next failing
 * call on the same thread.
 * @return A thread-local string, never NULL; credentials in URLs are already redacted.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_last_error(void);

/**
 * `text` with the password of every URL in it replaced by `***` (`rtsp://admin:S3cret@host/x` becomes
 * `rtsp://admin:***@host/x`): what a program prints of a camera spec. The library does it itself for every message
 * it gives (log lines, octocap_last_error(), camera statuses). NULL gives "". Valid until the next call on the same
 * thread.
 * @param[in] text A NUL-terminated string, or NULL.
 * @return A thread-local string, never NULL ("" also when memory ran out: nothing rather than the secret).
 * @since 1.9
 */
OCTOCAP_API const char* octocap_redact_credentials(const char* text);

/** Log levels. @since 0.1 */
typedef int32_t octocap_log_level_t;
/** Values of ::octocap_log_level_t. @since 0.1 */
enum octocap_log_level_values {
  OCTOCAP_LOG_DEBUG = 0,   /**< Detail for finding a fault. */
  OCTOCAP_LOG_INFO = 1,    /**< A normal event worth a line (an older program's config widened to today's). */
  OCTOCAP_LOG_WARNING = 2, /**< Work goes on in a lesser way (a GPU model run on the CPU, a frame set not solved). */
  OCTOCAP_LOG_ERROR = 3    /**< A failure no call returns (a live engine stopped, a recording's writes failed). */
};

/**
 * Log sink. May be called from any thread, including library worker threads; must not call back into octocap.
 * @param[in] level   The message's level, at least the min_level it was installed with.
 * @param[in] message The line, NUL-terminated, valid during the call only.
 * @param[in] user    The `user` given to octocap_set_log_callback().
 * @since 0.1
 */
typedef void (*octocap_log_callback_t)(octocap_log_level_t level, const char* message, void* user);

/**
 * Installs a process-wide log sink (NULL removes it) and the lowest level it receives. The library never
 * prints to stdout or stderr itself. Call it before creating handles, not while other threads use the library.
 * @param[in] callback  The sink, or NULL for none.
 * @param[in] min_level Messages below this level are not passed on.
 * @param[in] user      Passed back to every call of `callback`; the library never dereferences it.
 * @since 0.1
 */
OCTOCAP_API void octocap_set_log_callback(octocap_log_callback_t callback, octocap_log_level_t min_level, void* user);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Keypoint layouts and the skeleton (data that does not change per frame) */
/** @{ */

/** 2D keypoint layouts octocap reads. A layout is a table: names, order and mapping onto the skeleton. @since 0.1 */
typedef int32_t octocap_layout_t;
/** Values of ::octocap_layout_t. @since 0.1 */
enum octocap_layout_values {
  OCTOCAP_LAYOUT_AUTO = 0,      /**< Detect from the keypoint count (25 is taken as BODY_25). */
  OCTOCAP_LAYOUT_BODY_25 = 1,   /**< OpenPose BODY_25. */
  OCTOCAP_LAYOUT_BODY_25B = 2,  /**< OpenPose experimental BODY_25B (Pose2Sim's demo): COCO order + neck, head, feet. */
  OCTOCAP_LAYOUT_COCO_17 = 3,   /**< COCO-17 (MoveNet, RTMPose, YOLO-pose). */
  OCTOCAP_LAYOUT_HALPE_26 = 4,  /**< HALPE-26 (AlphaPose, RTMPose body7 halpe26). */
  OCTOCAP_LAYOUT_BLAZEPOSE_33 = 5 /**< MediaPipe BlazePose: face, COCO limbs, hand points, heels, foot tips.
                                       @since 1.4 */
};

/**
 * Number of keypoints of a layout.
 * @param[in] layout Any value.
 * @return The count, 0 for an unknown or AUTO layout.
 * @since 0.1
 */
OCTOCAP_API uint32_t octocap_layout_keypoint_count(octocap_layout_t layout);
/**
 * Static name of a layout ("BODY_25B").
 * @param[in] layout Any value.
 * @return A static string, or NULL for an unknown or AUTO layout.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_layout_name(octocap_layout_t layout);
/**
 * Parses a layout name (case-insensitive, "BODY_25B", "COCO_17", "COCO", ...).
 * @param[in]  name A NUL-terminated name.
 * @param[out] out  The layout.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `name` or `out` is NULL, or `name` is no known layout (the message lists
 *                                        them).
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_layout_from_name(const char* name, octocap_layout_t* out);
/**
 * Static name of keypoint `index` of `layout` ("RShoulder").
 * @param[in] layout A layout.
 * @param[in] index  0 .. octocap_layout_keypoint_count(layout) - 1.
 * @return A static string, or NULL for an unknown layout or an index out of range.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_layout_keypoint_name(octocap_layout_t layout, uint32_t index);

/**
 * The skeleton's joints: the paper's 14 plus a root at the hip centre, then (1.4) toes, heels and the hands'
 * knuckles. New joints are only ever appended, so an index keeps its meaning. A joint the layout has no keypoints for
 * (the feet of COCO_17, MoveNet's layout; the knuckles of every layout but BLAZEPOSE_33) is never valid.
 * @since 0.1
 */
typedef int32_t octocap_joint_id_t;
/** Values of ::octocap_joint_id_t. @since 0.1 */
enum octocap_joint_id_values {
  OCTOCAP_JOINT_HEAD = 0,        /**< The head: between the ears where the layout has them, else the nose. */
  OCTOCAP_JOINT_NECK = 1,        /**< The neck: the layout's neck keypoint, else between the shoulders. */
  OCTOCAP_JOINT_R_SHOULDER = 2,  /**< Right shoulder. */
  OCTOCAP_JOINT_R_ELBOW = 3,     /**< Right elbow. */
  OCTOCAP_JOINT_R_HAND = 4,      /**< Right wrist. */
  OCTOCAP_JOINT_L_SHOULDER = 5,  /**< Left shoulder. */
  OCTOCAP_JOINT_L_ELBOW = 6,     /**< Left elbow. */
  OCTOCAP_JOINT_L_HAND = 7,      /**< Left wrist. */
  OCTOCAP_JOINT_R_HIP = 8,       /**< Right hip. */
  OCTOCAP_JOINT_R_KNEE = 9,      /**< Right knee. */
  OCTOCAP_JOINT_R_FOOT = 10,     /**< Right ankle. */
  OCTOCAP_JOINT_L_HIP = 11,      /**< Left hip. */
  OCTOCAP_JOINT_L_KNEE = 12,     /**< Left knee. */
  OCTOCAP_JOINT_L_FOOT = 13,     /**< Left ankle. */
  OCTOCAP_JOINT_ROOT = 14,       /**< The root: the hip centre. */
  OCTOCAP_JOINT_R_TOE = 15,  /**< Right toes: between big and small toe, else the big toe. @since 1.4 */
  OCTOCAP_JOINT_L_TOE = 16,  /**< Left toes, as the right. @since 1.4 */
  OCTOCAP_JOINT_R_HEEL = 17, /**< Right heel. @since 1.4 */
  OCTOCAP_JOINT_L_HEEL = 18, /**< Left heel. @since 1.4 */
  OCTOCAP_JOINT_R_KNUCKLES = 19, /**< Right hand: between the index and little fingers' knuckles. @since 1.4 */
  OCTOCAP_JOINT_L_KNUCKLES = 20, /**< Left hand, as the right. @since 1.4 */
  OCTOCAP_JOINT_COUNT = 21   /**< The number of joints: 15 before 1.4. */
};

/**
 * Bones of the rig. ROOT carries the global orientation of the pelvis; every other bone goes from a parent
 * joint to a child joint and rotates relative to its parent bone. Every rotation is whole, twist included: the
 * upper arms and thighs roll with the plane of the bent elbow and knee (forearm and shin turn about their hinge),
 * the torso with the shoulder line, the head with ears, eyes and nose, the feet with the heel, the hands with the
 * palm (index to little finger knuckle: the hand's roll against the forearm is the forearm's twist, which an engine's
 * humanoid rig spreads over its twist bones). A roll that a frame cannot show (a straight limb, a face, heel or palm
 * not seen) holds its last value, easing back toward no roll of its own over a few seconds. New bones are only ever
 * appended (1.4: the feet and hands).
 * @since 0.1
 */
typedef int32_t octocap_bone_id_t;
/** Values of ::octocap_bone_id_t. @since 0.1 */
enum octocap_bone_id_values {
  OCTOCAP_BONE_ROOT = 0,         /**< The pelvis: root joint toward the left hip (its length is half the hip width). */
  OCTOCAP_BONE_TORSO = 1,        /**< Root to neck. */
  OCTOCAP_BONE_HEAD = 2,         /**< Neck to head. */
  OCTOCAP_BONE_R_SHOULDER = 3,   /**< Neck to right shoulder (the clavicle). */
  OCTOCAP_BONE_R_UPPER_ARM = 4,  /**< Right shoulder to elbow. */
  OCTOCAP_BONE_R_LOWER_ARM = 5,  /**< Right elbow to wrist. */
  OCTOCAP_BONE_L_SHOULDER = 6,   /**< Neck to left shoulder (the clavicle). */
  OCTOCAP_BONE_L_UPPER_ARM = 7,  /**< Left shoulder to elbow. */
  OCTOCAP_BONE_L_LOWER_ARM = 8,  /**< Left elbow to wrist. */
  OCTOCAP_BONE_R_UPPER_LEG = 9,  /**< Right hip to knee. */
  OCTOCAP_BONE_R_LOWER_LEG = 10, /**< Right knee to ankle. */
  OCTOCAP_BONE_L_UPPER_LEG = 11, /**< Left hip to knee. */
  OCTOCAP_BONE_L_LOWER_LEG = 12, /**< Left knee to ankle. */
  OCTOCAP_BONE_R_FOOT = 13, /**< Ankle (OCTOCAP_JOINT_R_FOOT) to toes. Rest: forward (+Z) and 20 deg down,
                                 as a foot standing flat, so that an avatar's foot at rest is near the template.
                                 @since 1.4 */
  OCTOCAP_BONE_L_FOOT = 14, /**< Left ankle to toes, as the right. @since 1.4 */
  OCTOCAP_BONE_R_HAND = 15, /**< Wrist (OCTOCAP_JOINT_R_HAND) to knuckles. Rest: along the arm, palm down.
                                 @since 1.4 */
  OCTOCAP_BONE_L_HAND = 16, /**< Left wrist to knuckles, as the right. @since 1.4 */
  OCTOCAP_BONE_COUNT = 17   /**< The number of bones: 13 before 1.4. */
};

/**
 * Static name of a skeleton joint ("r_elbow").
 * @param[in] joint An ::octocap_joint_id_t.
 * @return A static string, or NULL for a joint out of range.
 * @since 0.1
 */
OCTOCAP_API const char* octocap_joint_name(uint32_t joint);

/** Static description of one bone of the rig (the skeleton definition). @since 0.1 */
typedef struct octocap_bone_info_t {
  char name[OCTOCAP_NAME_CAPACITY]; /**< "r_upper_arm". */
  int32_t parent_bone;               /**< Parent bone index, -1 for ROOT. */
  int32_t head_joint;                /**< Joint the bone starts at (::octocap_joint_id_t). */
  int32_t tail_joint;                /**< Joint the bone ends at (::octocap_joint_id_t). */
  float rest_direction[3];           /**< Unit direction head->tail in the T-pose template, rig frame (Y up, facing +Z). */
} octocap_bone_info_t;

/**
 * Fills `out` with the definition of bone `bone`.
 * @param[in]  bone An ::octocap_bone_id_t.
 * @param[out] out  The bone's definition.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `bone` is not below ::OCTOCAP_BONE_COUNT.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_bone_info(uint32_t bone, octocap_bone_info_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Calibration */
/** @{ */

/** Opaque calibration: a set of cameras (intrinsics, distortion, pose). @since 0.1 */
typedef struct octocap_calibration_t octocap_calibration_t;

/** One camera, as stored in the anipose/Pose2Sim calibration TOML. @since 0.1 */
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

/**
 * Loads an anipose/Pose2Sim calibration TOML (`[cam_N]` tables, in file order).
 * @param[in]  path A file path.
 * @param[out] out  The new calibration (NULL on failure); destroy it with octocap_calibration_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` or `out` is NULL.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE            It is not TOML, has no camera table, or a camera's values are malformed
 *                                        (the message gives the line and the fault).
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The calibration could not be allocated.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_load(const char* path, octocap_calibration_t** out);
/**
 * Creates a calibration from `count` cameras.
 * @param[in]  cameras `count` cameras, in calibration order (copied).
 * @param[in]  count   1 or more.
 * @param[out] out     The new calibration (NULL on failure); destroy it with octocap_calibration_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cameras` or `out` is NULL, `count` is 0, or a camera is not one: NaN or
 *                                        infinite values, a size of 0 or above 100000, a focal length <= 0, a
 *                                        rotation that is none, a translation beyond a million metres.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The calibration could not be allocated.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_create(const octocap_camera_t* cameras, uint32_t count,
                                                        octocap_calibration_t** out);
/**
 * Writes the calibration as anipose/Pose2Sim TOML.
 * @param[in] calib A calibration.
 * @param[in] path  The file to write (replaced if it exists).
 * @retval OCTOCAP_OK                     The file is written.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` is NULL.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened or written.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_save(const octocap_calibration_t* calib, const char* path);
/**
 * Writes the calibration as OpenCV YAML (cv::FileStorage: camera_matrix, distortion_coefficients, rvec,
 * rotation_matrix, tvec per `cam_N`), for tools that read OpenCV's format.
 * @param[in] calib A calibration.
 * @param[in] path  The file to write (replaced if it exists).
 * @retval OCTOCAP_OK                     The file is written.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` is NULL.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened or written.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_calibration_save_opencv_yaml(const octocap_calibration_t* calib, const char* path);
/**
 * Number of cameras.
 * @param[in]  calib A calibration.
 * @param[out] out   The camera count.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_camera_count(const octocap_calibration_t* calib, uint32_t* out);
/**
 * Copies camera `index`.
 * @param[in]  calib A calibration.
 * @param[in]  index 0 .. camera count - 1.
 * @param[out] out   The camera.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `index` is out of range.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_get_camera(const octocap_calibration_t* calib, uint32_t index,
                                                            octocap_camera_t* out);
/**
 * Projects a world point (metres) into camera `index`, with distortion; pixel coordinates out.
 * @param[in]  calib     A calibration.
 * @param[in]  index     0 .. camera count - 1.
 * @param[in]  world     The point (x, y, z), world frame, metres.
 * @param[out] pixel_out Its pixel (x, y) in the camera's image.
 * @retval OCTOCAP_OK                     `pixel_out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `world` or `pixel_out` is NULL, `index` is out of range, the point is NaN
 *                                        or infinite, or it is behind the camera.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_calibration_project(const octocap_calibration_t* calib, uint32_t index,
                                                         const double world[3], double pixel_out[2]);
/**
 * Destroys a calibration; NULL is accepted. Sessions created from it keep their own copy.
 * @param[in] calib A calibration, or NULL.
 * @since 0.1
 */
OCTOCAP_API void octocap_calibration_destroy(octocap_calibration_t* calib);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/**
 * @name Frames: the one result type
 *
 * Every source of solved skeletons (a session, a stream subscriber, a motion file) hands out the same frame
 * handle, read with the same octocap_frame_* queries. A frame is an immutable snapshot: it stays valid, unchanged,
 * until it is released, whatever happens to its source afterwards (even its destruction), and may be read from any
 * thread. Each octocap_*_get_frame / take_frame call returns a new handle that the caller releases.
 *
 * A frame holds 0..N people, each with a stable `id` within its source, its layout keypoints, the skeleton's
 * joints and the bone poses. What does not change per frame (the keypoint layout's names, the bone table and its
 * rest directions) is the skeleton definition: read it once with octocap_layout_keypoint_name(),
 * octocap_joint_name() and octocap_bone_info(), and again when octocap_frame_summary_t.definition_counter changes.
 */
/** @{ */

/** Opaque, immutable, solved frame. @since 1.0 */
typedef struct octocap_frame_t octocap_frame_t;

/** A solved 3D point (a layout keypoint or a skeleton joint). @since 0.1 */
typedef struct octocap_joint_t {
  float position[3];           /**< Metres: the calibration's world frame, or the rig
                                    frame where octocap_frame_summary_t.joints_in_rig_frame says so. Zero when missing. */
  float confidence;            /**< Mean 2D confidence of the supporting views; 0 when missing. */
  float reprojection_error_px; /**< Mean distance (px) between the reprojection of the solved point (before the
                                    temporal filter) and the supporting detections. */
  uint32_t views_used;         /**< Number of views that supported the point. */
  uint32_t valid;              /**< 1 when solved, 0 when missing (never a guess). */
} octocap_joint_t;

/** Coordinate frame for bone queries. @since 0.1 */
typedef int32_t octocap_coord_frame_t;
/** Values of ::octocap_coord_frame_t. @since 0.1 */
enum octocap_coord_frame_values {
  OCTOCAP_FRAME_RIG = 0,    /**< Right-handed, Y up, character faces +Z in the T-pose. */
  OCTOCAP_FRAME_UNITY = 1,  /**< Left-handed, Y up, +Z forward (X mirrored). */
  OCTOCAP_FRAME_GODOT = 2   /**< Right-handed, Y up, character faces -Z (turned 180 degrees about Y). */
};

/** Quaternion (x, y, z, w). @since 0.1 */
typedef struct octocap_quat_t {
  /** @var octocap_quat_t::x
   *  The vector part's x: the rotation axis's x times the sine of half the angle. */
  /** @var octocap_quat_t::y
   *  The vector part's y: the rotation axis's y times the sine of half the angle. */
  /** @var octocap_quat_t::z
   *  The vector part's z: the rotation axis's z times the sine of half the angle. */
  /** @var octocap_quat_t::w
   *  The scalar part: the cosine of half the angle. */
  float x, y, z, w;
} octocap_quat_t;

/** The pose of one bone in a frame. @since 0.1 */
typedef struct octocap_bone_pose_t {
  octocap_quat_t local_rotation;  /**< Rotation relative to the parent bone, from the T-pose (identity = T-pose). */
  octocap_quat_t global_rotation; /**< Rotation in the chosen frame, from the T-pose. */
  float head_position[3];         /**< Where the bone starts, chosen frame, metres. */
  float length_m;                 /**< Measured length this frame. */
  uint32_t valid;                 /**< 0 when a joint of the bone is missing; rotations are then identity. */
} octocap_bone_pose_t;

/** What a frame holds. `struct_size` is set by the caller (sizeof); the library fills what it knows of that size.
 *  @since 1.0 */
typedef struct octocap_frame_summary_t {
  uint32_t struct_size;         /**< Set by the caller to sizeof(octocap_frame_summary_t). */
  uint32_t person_count;        /**< People in this frame (0 when nothing was solved), in increasing id order. A
                                     session solves one person unless its config's max_people says more; a DDS
                                     subscriber gives what its publisher solved; a motion file at most one. */
  int64_t frame_index;          /**< The source's frame number (a session starts at its first_frame_index). */
  int64_t timestamp_us;         /**< Frame time given to the solve (0 for motion files). */
  octocap_layout_t layout;      /**< Layout of the keypoints of every person. */
  uint32_t keypoint_count;      /**< Keypoints per person (the layout's count, 0 for motion files: joints only). */
  uint32_t definition_counter;  /**< Changes whenever the skeleton definition may have changed (another source,
                                     another layout): re-read the definition then. Never 0. */
  uint32_t source_id;           /**< The publisher's id for received frames; 0 for local sources. */
  uint32_t view_count;          /**< Views given to the solve (0 for motion files). */
  uint32_t joints_in_rig_frame; /**< 1 when joint and keypoint positions are in the rig frame (motion files), 0 when
                                     in the calibration's world frame. */
  float solve_ms;               /**< Wall time of the 3D solve (0 when not solved here). */
} octocap_frame_summary_t;

/** One person of a frame. `struct_size` is set by the caller. @since 1.0 */
typedef struct octocap_person_t {
  uint32_t struct_size;         /**< Set by the caller to sizeof(octocap_person_t). */
  uint32_t id;                  /**< Stable within the source while the person is tracked; never 0, never reused
                                     within a session (1 for a one-person session). Bind an avatar to it. */
  uint32_t keypoints_solved;    /**< Layout keypoints with valid = 1. */
  uint32_t keypoints_total;     /**< Layout keypoints. */
  uint32_t joints_solved;       /**< Skeleton joints with valid = 1. */
  uint32_t views_with_person;   /**< Views in which this person was seen. */
  float mean_reprojection_error_px; /**< Mean over the solved keypoints (before the temporal filter). */
  float confidence;             /**< Mean 2D confidence over the solved keypoints. */
  /* 1.11 */
  uint32_t foot_contacts;       /**< Feet planted on the floor this frame: ::OCTOCAP_FOOT_RIGHT, ::OCTOCAP_FOOT_LEFT
                                     (0: none, or no ankle solved). A foot is planted while its ankle is still and
                                     at the height a standing ankle has (learnt from the person's feet), with
                                     hysteresis; causal, known on the frame it happens. An engine runs its own foot
                                     IK on it; octocap_session_config_t.foot_lock holds planted ankles itself.
                                     Received frames and motion files give 0. @since 1.11 */
} octocap_person_t;

/** octocap_person_t.foot_contacts: the right foot is planted. @since 1.11 */
#define OCTOCAP_FOOT_RIGHT 1u
/** octocap_person_t.foot_contacts: the left foot is planted. @since 1.11 */
#define OCTOCAP_FOOT_LEFT 2u

/**
 * Fills `out` (whose struct_size the caller set).
 * @param[in]     frame A frame.
 * @param[in,out] out   Its struct_size set by the caller (at least sizeof(octocap_frame_summary_t) of this header);
 *                      the rest is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_summary(const octocap_frame_t* frame, octocap_frame_summary_t* out);
/**
 * Person `person` (0 .. person_count - 1).
 * @param[in]     frame  A frame.
 * @param[in]     person 0 .. person_count - 1.
 * @param[in,out] out    Its struct_size set by the caller; the rest is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `person` is out of range.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_person(const octocap_frame_t* frame, uint32_t person,
                                                      octocap_person_t* out);
/**
 * The layout keypoints of `person` in 3D (two-call pattern: NULL `out` gives the count; BUFFER_TOO_SMALL when
 * `capacity` is short, with the count set).
 * @param[in]  frame    A frame.
 * @param[in]  person   0 .. person_count - 1.
 * @param[out] out      `capacity` points, in the layout's order; or NULL to learn the count.
 * @param[in]  capacity Points `out` holds.
 * @param[out] count    The keypoint count, set also when the buffer is short.
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, or `person` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below `*count`.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_keypoints3d(const octocap_frame_t* frame, uint32_t person,
                                                           octocap_joint_t* out, uint32_t capacity, uint32_t* count);
/**
 * The ::OCTOCAP_JOINT_COUNT skeleton joints of `person` (two-call pattern). A caller built before joints were
 * appended (a capacity of at least 15, its OCTOCAP_JOINT_COUNT, but less than today's) gets the first `capacity`
 * joints, count set to that, and OCTOCAP_OK: new joints never break an old caller.
 * @param[in]  frame    A frame.
 * @param[in]  person   0 .. person_count - 1.
 * @param[out] out      `capacity` joints, in ::octocap_joint_id_values order; or NULL to learn the count.
 * @param[in]  capacity Joints `out` holds.
 * @param[out] count    The joints given (or needed).
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, or `person` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below 15.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_joints(const octocap_frame_t* frame, uint32_t person,
                                                      octocap_joint_t* out, uint32_t capacity, uint32_t* count);
/**
 * The ::OCTOCAP_BONE_COUNT bone poses of `person`, converted to `coord_frame` (two-call pattern; as for joints,
 * a capacity of at least 13, the count before 1.4, gets that many bones and OCTOCAP_OK).
 * @param[in]  frame       A frame.
 * @param[in]  person      0 .. person_count - 1.
 * @param[in]  coord_frame The frame to give rotations and positions in.
 * @param[out] out         `capacity` poses, in ::octocap_bone_id_values order; or NULL to learn the count.
 * @param[in]  capacity    Poses `out` holds.
 * @param[out] count       The bones given (or needed).
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, `person` is out of range, or `coord_frame` is no
 *                                         ::octocap_coord_frame_values.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below 13.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_bones(const octocap_frame_t* frame, uint32_t person,
                                                     octocap_coord_frame_t coord_frame, octocap_bone_pose_t* out,
                                                     uint32_t capacity, uint32_t* count);
/**
 * For each view, the index of the 2D person (in the solve's input) that became `person`, -1 where none; count =
 * view_count (two-call pattern).
 * @param[in]  frame    A frame.
 * @param[in]  person   0 .. person_count - 1.
 * @param[out] out      `capacity` indices, in calibration order; or NULL to learn the count.
 * @param[in]  capacity Indices `out` holds.
 * @param[out] count    The view count, set also when the buffer is short.
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `frame` is not a live frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, or `person` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below `*count`.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_frame_get_person_views(const octocap_frame_t* frame, uint32_t person,
                                                            int32_t* out, uint32_t capacity, uint32_t* count);
/**
 * Releases a frame; NULL is accepted.
 * @param[in] frame A frame, or NULL.
 * @since 1.0
 */
OCTOCAP_API void octocap_frame_release(octocap_frame_t* frame);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name 2D detection (ONNX Runtime): people's keypoints in camera images */
/** @{ */

/** One 2D keypoint in pixels. confidence <= 0 (or x, y = 0, 0 as OpenPose writes it) means "not detected".
 *  @since 0.1 */
typedef struct octocap_keypoint2d_t {
  float x;          /**< Pixels from the left (the centre of the first column is 0). */
  float y;          /**< Pixels from the top (the centre of the first row is 0). */
  float confidence; /**< The detector's score, 0 .. 1; <= 0: not detected. */
} octocap_keypoint2d_t;

/** Longest path a config holds, including the terminating NUL. @since 0.3 */
#define OCTOCAP_PATH_CAPACITY 512

/** Pixel layout of a camera image. @since 0.3 */
typedef int32_t octocap_pixel_format_t;
/** Values of ::octocap_pixel_format_t. @since 0.3 */
enum octocap_pixel_format_values {
  OCTOCAP_PIXELS_RGB8 = 0,  /**< 3 bytes per pixel, R G B (most decoders, Unity's RGB24). */
  OCTOCAP_PIXELS_BGR8 = 1,  /**< 3 bytes per pixel, B G R (OpenCV). */
  OCTOCAP_PIXELS_RGBA8 = 2  /**< 4 bytes per pixel, R G B A (Unity's RGBA32, Godot's FORMAT_RGBA8); alpha ignored. */
};

/** One camera image, borrowed for the duration of the call (never copied beyond it). An image with NULL pixels and
 *  a zero width and height is "no picture from this camera this frame" (it lagged, dropped, is reconnecting): the
 *  view is solved without.
 *  @since 0.3 */
typedef struct octocap_image_t {
  const uint8_t* pixels;          /**< Top row first. */
  uint32_t width;                 /**< Pixels. */
  uint32_t height;                /**< Pixels. */
  uint32_t stride_bytes;          /**< Bytes from one row to the next (>= width * bytes per pixel). */
  octocap_pixel_format_t format;  /**< See ::octocap_pixel_format_values. */
} octocap_image_t;

/** How N views are given to the network. @since 0.3 */
typedef int32_t octocap_detect_mode_t;
/** Values of ::octocap_detect_mode_t. @since 0.3 */
enum octocap_detect_mode_values {
  OCTOCAP_DETECT_PER_VIEW = 0, /**< One inference per view on the whole view, letterboxed. */
  OCTOCAP_DETECT_MOSAIC = 1,   /**< The paper's merged image: every view down-sampled into one tile, one inference
                                    (needs a multi-person model, default movenet-multipose). */
  OCTOCAP_DETECT_CROP = 2      /**< One inference per view on a crop around where the person was last frame (the
                                    last 3D joints reprojected), found on the whole view first. Most accurate. */
};

/** Which people found in one view go on to the 3D solve. @since 0.3 */
typedef int32_t octocap_person_pick_t;
/** Values of ::octocap_person_pick_t. @since 0.3 */
enum octocap_person_pick_values {
  OCTOCAP_PICK_ALL = 0,             /**< Up to max_people, best score first; the session picks across views. */
  OCTOCAP_PICK_LARGEST = 1,         /**< The person with the biggest box. */
  OCTOCAP_PICK_MOST_CONFIDENT = 2,  /**< The person the model is surest of. */
  OCTOCAP_PICK_NEAREST_PREVIOUS = 3 /**< Closest to last frame's reprojected joints (else most confident). */
};

/** Where the detector's network runs. @since 1.5 */
typedef int32_t octocap_device_t;
/** Values of ::octocap_device_t. @since 1.5 */
enum octocap_device_values {
  OCTOCAP_DEVICE_CPU = 0,  /**< ONNX Runtime's CPU kernels (every build). */
  OCTOCAP_DEVICE_AUTO = 1, /**< An NVIDIA GPU through ONNX Runtime's CUDA execution provider when this ONNX Runtime
                                has it and a GPU answers, else the CPU (logged as a warning, never an error);
                                octocap_detect_info_t.device says which ran. */
  OCTOCAP_DEVICE_CUDA = 2  /**< The GPU or nothing: creating the detector fails with ::OCTOCAP_ERROR_UNSUPPORTED
                                and a message saying what is missing (the GPU build of ONNX Runtime, installed with
                                `scripts/install-deps.sh --gpu`; CUDA libraries; a GPU). */
};

/** The inference back end that runs the detector's network. Both read the same .onnx and its model card.
 *  @since 1.9 */
typedef int32_t octocap_runtime_t;
/** Values of ::octocap_runtime_t. @since 1.9 */
enum octocap_runtime_values {
  OCTOCAP_RUNTIME_AUTO = 0,        /**< OpenVINO on the CPU where the build has it (the faster of the two there, at
                                        the same keypoints: docs/detecting.md); ONNX Runtime on a GPU, for
                                        a quantised model (its card's "quantized": calibrated for ONNX Runtime's
                                        integer kernels) or where the build has no OpenVINO. */
  OCTOCAP_RUNTIME_ONNXRUNTIME = 1, /**< ONNX Runtime (CPU, or an NVIDIA GPU with the device setting). */
  OCTOCAP_RUNTIME_OPENVINO = 2     /**< OpenVINO's CPU plugin; ::OCTOCAP_ERROR_UNSUPPORTED in a build without it or
                                        with a GPU device. */
};

/** The arithmetic the network runs in. @since 1.9 */
typedef int32_t octocap_precision_t;
/** Values of ::octocap_precision_t. @since 1.9 */
enum octocap_precision_values {
  OCTOCAP_PRECISION_AUTO = 0,    /**< f32 today, in both back ends (bf16 was measured to move keypoints;
                                      docs/detecting.md "Inference back ends"). */
  OCTOCAP_PRECISION_F32 = 1,     /**< 32-bit floats everywhere: the model's own numbers. */
  OCTOCAP_PRECISION_REDUCED = 2  /**< bf16 where the CPU has it natively (AVX-512 BF16, AMX; elsewhere OpenVINO keeps
                                      f32 and octocap_detect_info_t.precision says so). OpenVINO only
                                      (::OCTOCAP_ERROR_UNSUPPORTED with ONNX Runtime). About twice as fast; confident
                                      keypoints within about 1 % of the picture of f32's, weak ones may be lost. */
};

/** Detector configuration. Fill with octocap_detector_config_init() first. @since 0.3 */
typedef struct octocap_detector_config_t {
  uint32_t struct_size;            /**< sizeof(octocap_detector_config_t). */
  char model[OCTOCAP_PATH_CAPACITY]; /**< A .onnx path (its model card, same name with .json, beside it) or the name
                                        of a shipped model ("movenet-thunder", "movenet-lightning",
                                        "movenet-multipose") looked up in $OCTOCAP_MODELS_DIR, else (1.9) in a
                                        `models` folder beside liboctocap (a package's), else in
                                        `<prefix>/share/octocap/models` of an installed library, else the build's
                                        models directory. Empty (default): movenet-thunder, or movenet-multipose
                                        for the mosaic. */
  octocap_detect_mode_t mode;      /**< Default ::OCTOCAP_DETECT_CROP (of the three, the one that
                                      finds the most keypoints and solves closest to a reference 3D). */
  octocap_person_pick_t person_pick; /**< Default ::OCTOCAP_PICK_ALL. */
  uint32_t threads;                /**< Inference threads per view; 0 = all cores (shared by parallel views). Default 0. */
  uint32_t mosaic_tile_px;         /**< Mosaic: height of each view's tile (the width follows the views' aspect). Default 256. */
  uint32_t max_people;             /**< People kept per view with ::OCTOCAP_PICK_ALL. Default 4. */
  float min_confidence;            /**< Keypoints below it do not place a person in a mosaic tile or a crop. Default 0.3. */
  uint32_t parallel_views;         /**< Per view and crop: views inferred at once, each on its share of the cores
                                        (when threads = 0). 0 = one per core (default); 1 = one after another. */
  /* 1.5 */
  uint32_t views_per_frame;        /**< Detection scheduling (per view and crop): at most this many views run the
                                        network each frame; each other view follows its people from its previous
                                        picture by optical flow (about 1 ms a view instead of tens). Views that cannot
                                        be followed (nobody seen, no previous picture, a track that lost half its
                                        keypoints) are detected anyway; of the rest, those detected longest ago. 0 =
                                        every view every frame. Default 0. See docs/benchmarks.md "Real time" for
                                        what each value measures. @since 1.5 */
  octocap_device_t device;         /**< Where the network runs: ::OCTOCAP_DEVICE_CPU (default), ::OCTOCAP_DEVICE_AUTO or
                                        ::OCTOCAP_DEVICE_CUDA. @since 1.5 */
  /* 1.9 */
  octocap_runtime_t runtime;       /**< The inference back end. Default ::OCTOCAP_RUNTIME_AUTO. @since 1.9 */
  octocap_precision_t precision;   /**< Its arithmetic. Default ::OCTOCAP_PRECISION_AUTO. @since 1.9 */
} octocap_detector_config_t;

/**
 * Fills the first `struct_size` bytes of `cfg` with defaults and sets its struct_size: ::OCTOCAP_ERROR_STRUCT_SIZE
 * for a size no version of this header had. Call it through octocap_detector_config_init().
 * @param[out] cfg         The config to fill, `struct_size` bytes of it.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_detector_config_t) of its header.
 * @retval OCTOCAP_OK                     `cfg` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no released size of the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_detector_config_defaults(octocap_detector_config_t* cfg, uint32_t struct_size);
/**
 * Fills `cfg` with this library's defaults. Inline, so that it never writes past the struct the caller was built with.
 * @param[out] cfg The config to fill.
 * @since 0.3 (an exported function until 1.0, inline over octocap_detector_config_defaults() since)
 */
static inline void octocap_detector_config_init(octocap_detector_config_t* cfg) {
  (void)octocap_detector_config_defaults(cfg, (uint32_t)sizeof *cfg);
}

/** Figures of the last detection. @since 0.3 */
typedef struct octocap_detect_info_t {
  uint32_t struct_size;       /**< Set by the caller to sizeof(octocap_detect_info_t). */
  float total_ms;             /**< Whole detection of the frame (all views). */
  float preprocess_ms;        /**< Resizing, letterboxing, tiling. */
  float inference_ms;         /**< Inside the inference back end. */
  uint32_t inferences;        /**< Network runs for the frame (1 for the mosaic, N per view, up to 2N for crops). */
  octocap_layout_t layout;    /**< The model's keypoint layout. */
  uint32_t keypoint_count;    /**< Keypoints per person. */
  char model[OCTOCAP_NAME_CAPACITY]; /**< The model card's name. */
  /* 1.3 */
  octocap_detect_mode_t mode;  /**< How the views were detected: the config's mode, except that a session solving
                                    several people with no model named runs the multi-person model on whole views
                                    (::OCTOCAP_DETECT_PER_VIEW: measured best there). @since 1.3 */
  /* 1.5 */
  uint32_t views_tracked;      /**< Views followed by optical flow instead of detected (views_per_frame). @since 1.5 */
  float track_ms;              /**< Optical flow: preparing every view's picture, following the tracked views.
                                    @since 1.5 */
  octocap_device_t device;     /**< Where the network ran: ::OCTOCAP_DEVICE_CPU or ::OCTOCAP_DEVICE_CUDA. @since 1.5 */
  /* 1.9 */
  octocap_runtime_t runtime;     /**< The back end that ran it: ::OCTOCAP_RUNTIME_ONNXRUNTIME or ::OCTOCAP_RUNTIME_OPENVINO.
                                      @since 1.9 */
  octocap_precision_t precision; /**< Its arithmetic: ::OCTOCAP_PRECISION_F32 or ::OCTOCAP_PRECISION_REDUCED.
                                      @since 1.9 */
} octocap_detect_info_t;

/** A 2D detector on its own (no calibration): what `octocap detect` uses to write OpenPose JSON. @since 0.3 */
typedef struct octocap_detector_t octocap_detector_t;

/**
 * Loads the model.
 * @param[in]  cfg A config filled with octocap_detector_config_init() first.
 * @param[out] out The new detector (NULL on failure); destroy it with octocap_detector_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new detector.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` or `out` is NULL, a config value is out of range or the model path not
 *                                        NUL-terminated, a model whose inputs or outputs do not fit its card, or a
 *                                        mosaic with a single-person model.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_IO               A missing model or card.
 * @retval OCTOCAP_ERROR_PARSE            A malformed card or model.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      A build without ONNX Runtime (or without OpenVINO for that runtime), a
 *                                        library older than the headers octocap was built with, no GPU for
 *                                        ::OCTOCAP_DEVICE_CUDA, or a runtime, device and precision that do not go
 *                                        together.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The network could not be allocated.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_detector_create(const octocap_detector_config_t* cfg, octocap_detector_t** out);
/**
 * Destroys a detector; NULL is accepted.
 * @param[in] detector A detector, or NULL.
 * @since 0.3
 */
OCTOCAP_API void octocap_detector_destroy(octocap_detector_t* detector);
/**
 * Detects people in `count` images (views of one instant, or unrelated pictures).
 * @param[in] detector A detector.
 * @param[in] images   `count` images, borrowed for the call.
 * @param[in] count    1 or more.
 * @retval OCTOCAP_OK                     The people are found (read them with octocap_detector_people()).
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `detector` is not a live detector.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `images` is NULL, `count` is 0, or an image is bad (NULL pixels, zero
 *                                        size, short stride, unknown format, a side above 16384); also a model that
 *                                        fails on the picture.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_detector_run(octocap_detector_t* detector, const octocap_image_t* images,
                                                  uint32_t count);
/**
 * People found in image `view` by the last run, best first.
 * @param[in]  detector A detector.
 * @param[in]  view     0 .. the last run's image count - 1.
 * @param[out] count    The number of people.
 * @retval OCTOCAP_OK                     `*count` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `detector` is not a live detector.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL, or `view` is out of range (also before the first run).
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_detector_people(const octocap_detector_t* detector, uint32_t view,
                                                     uint32_t* count);
/**
 * Keypoints (image pixels, the model's layout) of one person of the last run (two-call pattern).
 * @param[in]  detector A detector.
 * @param[in]  view     0 .. the last run's image count - 1.
 * @param[in]  person   0 .. octocap_detector_people() - 1.
 * @param[out] out      `capacity` keypoints; or NULL to learn the count.
 * @param[in]  capacity Keypoints `out` holds.
 * @param[out] count    The model layout's keypoint count, set also when the buffer is short.
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `detector` is not a live detector.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, or `view` or `person` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below `*count`.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_detector_keypoints(const octocap_detector_t* detector, uint32_t view,
                                                        uint32_t person, octocap_keypoint2d_t* out,
                                                        uint32_t capacity, uint32_t* count);
/**
 * Figures of the last run (model, layout, timings).
 * @param[in]     detector A detector.
 * @param[in,out] out      Its struct_size set by the caller (the size of any released header's struct); the rest
 *                         is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `detector` is not a live detector.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is no released size of the struct.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_detector_info(const octocap_detector_t* detector, octocap_detect_info_t* out);
/**
 * The keypoint layout a model gives (a shipped name, or an .onnx path with its card beside it), read from its
 * model card without loading the network: what a session solving that model's detections is created with. An empty
 * name is the default model.
 * @param[in]  model  A shipped model's name, an .onnx path, or "".
 * @param[out] layout The model's keypoint layout.
 * @retval OCTOCAP_OK                     `*layout` is set.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `model` or `layout` is NULL.
 * @retval OCTOCAP_ERROR_IO               No card.
 * @retval OCTOCAP_ERROR_PARSE            A malformed card.
 * @since 1.5
 */
OCTOCAP_API octocap_result_t octocap_model_layout(const char* model, octocap_layout_t* layout);
/**
 * Version of the ONNX Runtime library in use ("1.32.0"), or "" when this build has none (or the library is
 * older than octocap's headers). The string stays valid until the next call on the same thread.
 * @return A thread-local string, never NULL.
 * @since 0.3
 */
OCTOCAP_API const char* octocap_onnxruntime_version(void);
/**
 * Version of the OpenVINO library in use ("2026.4.0-..."), or "" when this build has none. The string stays
 * valid until the next call on the same thread.
 * @return A thread-local string, never NULL.
 * @since 1.9
 */
OCTOCAP_API const char* octocap_openvino_version(void);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Recorded takes: the cameras' pictures, frame by frame
 *
 * A take on disk is a folder holding one video per camera (.mp4, .avi, .mov, .mkv, .webm), or one sub-folder of
 * pictures per camera (.png, .jpg, .jpeg, .bmp, .tif, .tiff), sorted by name: the order the calibration lists its
 * cameras in. A take reader decodes it with the same code that plays files as cameras in a live capture, and hands
 * out each frame's pictures ready for octocap_session_solve_images() or octocap_detector_run():
 *
 *     octocap_take_reader_t* take;  octocap_take_reader_open("take/videos", &take);
 *     octocap_take_info_t info = {sizeof info};  octocap_take_reader_info(take, &info);
 *     octocap_image_t images[8];  uint32_t n;
 *     for (uint32_t f = 0; f < info.frame_count; ++f) {
 *       octocap_take_reader_read(take, f, images, 8, &n);
 *       octocap_session_solve_images(session, images, n, (int64_t)(f * 1e6 / 30));
 *     }
 *     octocap_take_reader_destroy(take);
 *
 * Thread rules: one reader is used by one thread at a time; distinct readers run in parallel. A reader decodes
 * the next frame on a thread of its own while the caller works on the one it was handed.
 */
/** @{ */

/** Opaque reader of a recorded take's pictures. @since 1.12 */
typedef struct octocap_take_reader_t octocap_take_reader_t;

/** What a take holds. @since 1.12 */
typedef struct octocap_take_info_t {
  uint32_t struct_size;      /**< Set by the caller to sizeof(octocap_take_info_t). */
  uint32_t camera_count;     /**< Cameras: videos or picture sub-folders. */
  uint32_t frame_count;      /**< Frames every camera has (the shortest camera's count). */
  uint32_t reserved;         /**< Zero. */
  double frames_per_second;  /**< The videos' rate (the first camera's: the log warns when another differs); 0 for
                                  picture folders, whose rate the caller knows. */
} octocap_take_info_t;

/**
 * Opens the take in `folder`.
 * @param[in]  folder A folder of videos, one per camera, or of sub-folders of pictures, one per camera.
 * @param[out] out    The new reader (NULL on failure); destroy it with octocap_take_reader_destroy().
 * @retval OCTOCAP_OK                     Opened; every camera's file or folder could be read.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `folder` or `out` is NULL.
 * @retval OCTOCAP_ERROR_IO               `folder` is not a folder, holds neither layout, or a video cannot be opened;
 *                                        the message names it.
 * @since 1.12
 */
OCTOCAP_API octocap_result_t octocap_take_reader_open(const char* folder, octocap_take_reader_t** out);

/**
 * Fills `out` with what the take holds.
 * @param[in]  reader A take reader.
 * @param[out] out    Its `struct_size` set by the caller.
 * @retval OCTOCAP_OK                     Filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `reader` is not a live take reader.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is not sizeof(octocap_take_info_t).
 * @since 1.12
 */
OCTOCAP_API octocap_result_t octocap_take_reader_info(const octocap_take_reader_t* reader, octocap_take_info_t* out);

/**
 * The name of camera `camera`: its video's file name without the extension, or its sub-folder's name (as a
 * detection's OpenPose folders and the calibration's `name` call it).
 * @param[in]  reader A take reader.
 * @param[in]  camera 0 .. camera_count - 1.
 * @param[out] name   A UTF-8 string owned by the reader, valid until octocap_take_reader_destroy().
 * @retval OCTOCAP_OK                     `*name` set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `reader` is not a live take reader.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `name` is NULL or `camera` is out of range.
 * @since 1.12
 */
OCTOCAP_API octocap_result_t octocap_take_reader_camera_name(const octocap_take_reader_t* reader, uint32_t camera,
                                                             const char** name);

/**
 * Reads frame `frame` of every camera. Frames read in order cost one decode each (the next one decodes while the
 * caller works); going back, or jumping ahead in a video, costs a seek or the frames between.
 * @param[in]  reader   A take reader.
 * @param[in]  frame    0 .. frame_count - 1.
 * @param[out] images   `capacity` images; camera c's picture goes to `images[c]`, ::OCTOCAP_PIXELS_BGR8. The
 *                      pixels belong to the reader and stay valid until its next octocap_take_reader_read() or
 *                      octocap_take_reader_destroy(): read them, do not write them.
 * @param[in]  capacity Images `images` holds (at least camera_count).
 * @param[out] count    Set to camera_count; may be NULL.
 * @retval OCTOCAP_OK                      Every camera's picture is in `images`.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `reader` is not a live take reader.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `images` is NULL or `frame` is past the take's end.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below camera_count (`*count` tells it).
 * @retval OCTOCAP_ERROR_IO                A camera's picture cannot be read or decoded; the message names the camera
 *                                         and the frame. The reader stays usable for other frames.
 * @since 1.12
 */
OCTOCAP_API octocap_result_t octocap_take_reader_read(octocap_take_reader_t* reader, uint32_t frame,
                                                      octocap_image_t* images, uint32_t capacity, uint32_t* count);

/**
 * Destroys a take reader; its pictures are gone. NULL is accepted.
 * @param[in] reader A take reader, or NULL.
 * @since 1.12
 */
OCTOCAP_API void octocap_take_reader_destroy(octocap_take_reader_t* reader);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Session: one capture, solved frame by frame */
/** @{ */

/** Opaque session: solver state for one capture (previous frame, filter, person tracking). @since 0.1 */
typedef struct octocap_session_t octocap_session_t;

/** 3D method. @since 0.1 */
typedef int32_t octocap_method_t;
/** Values of ::octocap_method_t. @since 0.1 */
enum octocap_method_values {
  OCTOCAP_METHOD_SUBDIVISION = 0,   /**< The paper's iterative space subdivision. */
  OCTOCAP_METHOD_TRIANGULATION = 1, /**< Confidence-weighted DLT with outlier-view rejection. */
  OCTOCAP_METHOD_AUTO = 2           /**< Subdivision with 5 or more cameras, triangulation with fewer (the more
                                         accurate of the two for each case). @since 0.2 */
};

/** Temporal filter. @since 0.1 */
typedef int32_t octocap_filter_t;
/** Values of ::octocap_filter_t. @since 0.1 */
enum octocap_filter_values {
  OCTOCAP_FILTER_NONE = 0,          /**< No temporal filter: each frame's points as solved. */
  OCTOCAP_FILTER_ONE_EURO = 1,      /**< Causal One Euro filter: smooth when slow, no lag when fast. (1.4) Its minimum
                                         cutoff follows each keypoint's measured noise (its reprojection error): where
                                         the views agree within the 3 px it was tuned at, it smooths less (at 1 px as
                                         good as no filter), never more than the fixed filter. */
  OCTOCAP_FILTER_ONE_EURO_FIXED = 2 /**< The One Euro filter with its minimum cutoff fixed (before 1.4's).
                                         @since 1.4 */
};

/** QoS profile of a skeleton stream; publisher and subscriber must use the same one. @since 0.2 */
typedef int32_t octocap_stream_qos_t;
/** Values of ::octocap_stream_qos_t. @since 0.2 */
enum octocap_stream_qos_t_values {
  OCTOCAP_QOS_LIVE = 0,   /**< BEST_EFFORT, VOLATILE, KEEP_LAST 1: the newest pose, never an old one late (engines). */
  OCTOCAP_QOS_RECORD = 1  /**< RELIABLE, TRANSIENT_LOCAL, KEEP_LAST depth: every frame; late joiners get the last
                               `depth` poses (recorders). */
};

/** Up axis of the calibration's world frame. @since 0.1 */
typedef int32_t octocap_up_axis_t;
/** Values of ::octocap_up_axis_t. @since 0.1 */
enum octocap_up_axis_values {
  OCTOCAP_UP_Y = 0,    /**< Y up (octocap's convention). */
  OCTOCAP_UP_Z = 1,    /**< Z up (Qualisys, Pose2Sim calibrations, most lab systems). */
  OCTOCAP_UP_AUTO = 2  /**< Decide from the cameras: upright cameras' image "down" axes point to world down.
                            @since 0.2 */
};

/**
 * Session configuration. Fill it with octocap_session_config_init(), then change what you need. The 2D detector of
 * octocap_session_solve_images() is configured apart (octocap_session_set_detector()), so that either struct can
 * grow without the other.
 * @since 0.1
 */
typedef struct octocap_session_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_session_config_t); set by octocap_session_config_init(). */
  octocap_layout_t layout;       /**< Keypoint layout of the 2D input (AUTO is not allowed here). Default BODY_25. */
  octocap_method_t method;       /**< Default AUTO; see octocap_session_method() for the resolved one. */
  octocap_filter_t filter;       /**< Default ONE_EURO. */
  octocap_up_axis_t up_axis;     /**< Default AUTO; see octocap_session_up_axis() for the resolved one. */
  uint32_t sigma;                /**< Views a cube must be supported by. 0 = camera count - 1 (min 2). Clamped to the views that saw the joint, never below min_views. */
  uint32_t min_views;            /**< Fewest views a joint is solved from. Default 2. */
  float delta_m;                 /**< Smallest cube edge, metres. Default 0.01; at least 0.001. */
  float pixel_tolerance;         /**< Subdivision: a detection within this many pixels of a cube's projection supports it. Default 4. */
  uint32_t max_candidates;       /**< Subdivision: candidate cubes kept per level, best supported and closest to the rays first
                                      (bounds the cost). Default 8; at most 4096. */
  float min_confidence;          /**< 2D keypoints below this confidence are treated as missing. Default 0.3. */
  float outlier_threshold_px;    /**< A view farther than this from the joint's reprojection is rejected. Default 15. */
  float volume_min[3];           /**< Capture volume (world, metres). When min == max, it is derived from the calibration. */
  float volume_max[3];           /**< Its far corner: greater than volume_min on every axis, or equal to it. */
  float filter_min_cutoff_hz;    /**< One Euro min cutoff. Default 1.5. */
  float filter_beta;             /**< One Euro speed coefficient (1/m). Default 20. */
  uint32_t worker_threads;       /**< Threads used across joints; 0 = hardware concurrency, 1 = none. At most 256. */
  int64_t first_frame_index;     /**< Frame numbers start here (default 0): a resumed take keeps its numbering.
                                      0 .. 2^62. @since 0.2 */
  uint32_t stream_enable;        /**< 1: publish every solved frame over DDS (see "Streaming"). Default 0. @since 0.2 */
  uint32_t stream_domain_id;     /**< DDS domain. Default 0. @since 0.2 */
  octocap_stream_qos_t stream_qos; /**< Default ::OCTOCAP_QOS_LIVE. @since 0.2 */
  uint32_t stream_history_depth; /**< Poses a RECORD stream keeps for late joiners. Default 256. @since 0.2 */
  uint32_t stream_source_id;     /**< Identifies this rig on a shared topic (the DDS key). Default 1. @since 0.2 */
  char stream_topic[OCTOCAP_NAME_CAPACITY]; /**< Topic base name, "<name>_pose" (or "<name>_people" with
                                      max_people != 1) and "<name>_definition". Default "octocap". @since 0.2 */
  uint32_t vmc_port;             /**< Non-zero: also send every frame as VMC protocol (OSC/UDP) to this port;
                                      VMC's usual port is ::OCTOCAP_VMC_DEFAULT_PORT. Default 0 (off). A VMC
                                      receiver drives one avatar: with max_people != 1, person slot n goes to
                                      vmc_port + n (slots: max_people, or ::OCTOCAP_MAX_PEOPLE for 0). A person keeps
                                      their slot while tracked, a newcomer takes the lowest free one, and a slot
                                      whose person left is sent /VMC/Ext/OK 0 once. @since 0.2 */
  char vmc_host[64];             /**< Receiver of the VMC output. Default "127.0.0.1". @since 0.2 */
  /* 1.3 */
  uint32_t max_people;           /**< People solved per frame. 1 (default): one person, the one the views agree on,
                                      followed over time (bystanders ignored). N > 1: up to N people, associated
                                      across views and tracked with stable ids (octocap_person_t.id; a person who
                                      leaves and comes back within a few seconds keeps the id when place and build
                                      say it is the same person; ids are never reused within a session). 0: everyone
                                      there, up to ::OCTOCAP_MAX_PEOPLE. People whose body is outside the capture
                                      volume (volume_min/max) are not solved. @since 1.3 */
  /* 1.10 */
  uint32_t reserved_1_10;        /**< Unused, ignored: it fills what was 1.3's padding (a 1.3 caller's bytes there are
                                      not zeroed), so that nothing of 1.10 is read from it. @since 1.10 */
  char stream_security[OCTOCAP_PATH_CAPACITY]; /**< "" (default): the stream is plain DDS. A keystore identity
                                      folder (KEYSTORE/NAME, made by octocap_keystore_add_identity(), role HUB): the
                                      stream is published over DDS Security, readable only by identities of the same
                                      keystore whose role may read it (see "Securing the network"). @since 1.10 */
  /* 1.11 */
  uint32_t foot_lock;            /**< 1 (default since 1.13; 0 in 1.11 and 1.12): a foot planted on the floor holds
                                      still (octocap_person_t.foot_contacts says which): its ankle stays where it
                                      stands while the solve's noise would make it skate, and its knee and foot
                                      follow. From pixels (CMU motion, four cameras) the planted ankle moves 2 to 4
                                      times less, for MPJPE within 0.2 mm of unlocked; nothing above the knees
                                      changes, and the next frame's crops follow the measured feet. 0: joints as
                                      solved. Contacts are reported either way. A program built against an older
                                      header (no such field) gets the default too. @since 1.11 */
  uint32_t reserved_1_11;        /**< Unused, ignored: keeps the struct free of padding. @since 1.11 */
} octocap_session_config_t;

/** The most people one frame holds (octocap_session_config_t.max_people = 0). @since 1.3 */
#define OCTOCAP_MAX_PEOPLE 16

/**
 * Fills the first `struct_size` bytes of `cfg` with defaults and sets its struct_size. Call it through
 * octocap_session_config_init().
 * @param[out] cfg         The config to fill, `struct_size` bytes of it.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_session_config_t) of its header.
 * @retval OCTOCAP_OK                     `cfg` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no size a version of this header had.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_session_config_defaults(octocap_session_config_t* cfg, uint32_t struct_size);
/**
 * Fills `cfg` with this library's defaults. Inline, so that it never writes past the struct the caller was built with.
 * @param[out] cfg The config to fill.
 * @since 0.1 (an exported function until 1.0, inline over octocap_session_config_defaults() since)
 */
static inline void octocap_session_config_init(octocap_session_config_t* cfg) {
  (void)octocap_session_config_defaults(cfg, (uint32_t)sizeof *cfg);
}

/**
 * Creates a session. `calib` is copied; it may be destroyed afterwards.
 * @param[in]  cfg   A config filled with octocap_session_config_init() first.
 * @param[in]  calib The cameras (2 to 64), copied.
 * @param[out] out   The new session (NULL on failure); destroy it with octocap_session_destroy().
 * @retval OCTOCAP_OK                      `*out` is a new session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `cfg` or `out` is NULL, NaN or out-of-range values, a config whose
 *                                         per-frame cost has no bound, fewer cameras than min_views, more than 64
 *                                         cameras, cameras that share no field of view (give the volume), an
 *                                         unterminated text field, or a stream_security identity that
 *                                         octocap_keystore_check_identity() refuses so (expired, not signed by its
 *                                         CA) or whose role may not publish.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE       `cfg->struct_size` is no size a version of this header had.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  The calibration has fewer than 2 cameras.
 * @retval OCTOCAP_ERROR_UNSUPPORTED       Streaming or VMC output asked of a build without DDS.
 * @retval OCTOCAP_ERROR_IO                The DDS participant could not be made, or a stream_security file is missing.
 * @retval OCTOCAP_ERROR_PARSE             A stream_security file is not what it should be.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     The session could not be allocated.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_session_create(const octocap_session_config_t* cfg,
                                                    const octocap_calibration_t* calib,
                                                    octocap_session_t** out);
/**
 * Destroys a session; NULL is accepted. Frames taken from it stay valid.
 * @param[in] session A session, or NULL.
 * @since 0.1
 */
OCTOCAP_API void octocap_session_destroy(octocap_session_t* session);

/**
 * Solves one frame from 2D keypoints.
 *
 * @param[in] session    A session.
 * @param[in] keypoints  Flat array: for view 0 its people one after the other, then view 1, ... Each person is
 *                   octocap_layout_keypoint_count(layout) keypoints in the layout's order. NaN, infinite,
 *                   zero-confidence and (0, 0) keypoints count as "not detected".
 * @param[in] people_per_view  view_count counts (0 = nobody detected in that view; at most 64), or NULL for exactly one
 *                   person per view. With several people in a view and max_people = 1, the session picks the one
 *                   who agrees with the other views and with the previous frame; with max_people != 1 it solves
 *                   each person the views agree on (in any order in each view), and the frame holds them all.
 * @param[in] view_count Must equal the calibration's camera count (cameras in calibration order).
 * @param[in] timestamp_us  Frame time in microseconds; must increase for the filter to work.
 * @retval OCTOCAP_OK                     A person was solved (some joints may still be missing: they are reported so).
 * @retval OCTOCAP_STATUS_NO_PERSON       Fewer than min_views views hold a person (the frame has no person and the
 *                                        session stays usable).
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH  `view_count` is not the calibration's camera count.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT NULL keypoints with people, or more than 64 people in a view.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed; the session stays usable.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_session_solve_keypoints(octocap_session_t* session,
                                                             const octocap_keypoint2d_t* keypoints,
                                                             const uint32_t* people_per_view,
                                                             uint32_t view_count, int64_t timestamp_us);

/**
 * Sets the 2D detector octocap_session_solve_images() uses, and loads its model now (without a call, the default
 * detector is loaded on the first octocap_session_solve_images()). The model must give the session's layout
 * (COCO_17 for the shipped models).
 * @param[in] session A session.
 * @param[in] cfg     A detector config filled with octocap_detector_config_init() first.
 * @retval OCTOCAP_OK                     The detector is loaded.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL, a model of another layout than the session's, or as for
 *                                        octocap_detector_create().
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_IO               As for octocap_detector_create(): a missing model or card.
 * @retval OCTOCAP_ERROR_PARSE            As for octocap_detector_create(): a malformed card or model.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      As for octocap_detector_create().
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The network could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_session_set_detector(octocap_session_t* session,
                                                          const octocap_detector_config_t* cfg);

/**
 * Solves one frame from camera images: 2D detection (see octocap_session_set_detector()), then the same solve as
 * octocap_session_solve_keypoints().
 *
 * @param[in] session      A session.
 * @param[in] images       view_count images in calibration order. An image at another size than its camera's
 *                         calibrated size is scaled to it when the aspect ratio is the same, and refused otherwise.
 * @param[in] view_count   Must equal the calibration's camera count.
 * @param[in] timestamp_us Frame time in microseconds; must increase for the filter to work.
 * @retval OCTOCAP_OK                     A person was solved.
 * @retval OCTOCAP_STATUS_NO_PERSON       Too few views hold a person (the session stays usable).
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH  `view_count` is not the calibration's camera count.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `images` is NULL, or a bad image (NULL pixels, zero size, short stride,
 *                                        unknown format, another aspect ratio than its camera's).
 * @retval OCTOCAP_ERROR_IO               On the first call without octocap_session_set_detector(): the default
 *                                        detector's errors, as for octocap_detector_create().
 * @retval OCTOCAP_ERROR_PARSE            The same, for a malformed model or card.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      The same, for a build without the runtime.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed; the session stays usable.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_session_solve_images(octocap_session_t* session, const octocap_image_t* images,
                                                          uint32_t view_count, int64_t timestamp_us);

/**
 * The last solved frame, as a new frame handle the caller releases with octocap_frame_release().
 * @param[in]  session A session.
 * @param[out] out     The new frame handle (NULL on failure).
 * @retval OCTOCAP_OK                     `*out` is a new frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The snapshot could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_session_get_frame(const octocap_session_t* session, octocap_frame_t** out);

/**
 * The 2D keypoints the detector found in `view` during the last octocap_session_solve_images(): every person kept
 * (keypoint_count each, the session's layout) one after the other; `count` = people x keypoints (two-call pattern).
 * Engines draw them over the camera image.
 * @param[in]  session  A session.
 * @param[in]  view     0 .. camera count - 1.
 * @param[out] out      `capacity` keypoints; or NULL to learn the count.
 * @param[in]  capacity Keypoints `out` holds.
 * @param[out] count    People x keypoints, set also when the buffer is short.
 * @retval OCTOCAP_OK                      `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT         No detector yet (before the first octocap_session_solve_images() or
 *                                         octocap_session_set_detector()).
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `count` is NULL, or `view` is out of range (also after
 *                                         octocap_session_set_detector() but before the first detection).
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL  `capacity` is below `*count`.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_session_detections(const octocap_session_t* session, uint32_t view,
                                                        octocap_keypoint2d_t* out, uint32_t capacity, uint32_t* count);

/**
 * Figures of the last octocap_session_solve_images() detection (`out->struct_size` set by the caller).
 * @param[in]     session A session.
 * @param[in,out] out     Its struct_size set by the caller; the rest is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        No detector yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is no released size of the struct.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_session_detect_info(const octocap_session_t* session, octocap_detect_info_t* out);

/**
 * The 3D method in use (AUTO resolved at creation).
 * @param[in]  session A session.
 * @param[out] out     ::OCTOCAP_METHOD_SUBDIVISION or ::OCTOCAP_METHOD_TRIANGULATION.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_session_method(const octocap_session_t* session, octocap_method_t* out);

/**
 * The up axis in use (AUTO resolved to Y or Z at creation).
 * @param[in]  session A session.
 * @param[out] out     ::OCTOCAP_UP_Y or ::OCTOCAP_UP_Z.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_session_up_axis(const octocap_session_t* session, octocap_up_axis_t* out);

/**
 * Number of subscribers currently matched to this session's pose stream (0 when not streaming): lets a
 * recording wait for its recorder before the take starts.
 * @param[in]  session A session.
 * @param[out] out     The number of matched readers (VMC receivers are not counted: UDP has no readers).
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_session_stream_subscribers(const octocap_session_t* session, uint32_t* out);

/**
 * Blocks until every frame this session published has been handed to DDS (no-op when not streaming).
 * @param[in] session A session.
 * @retval OCTOCAP_OK                   Every published frame is handed over.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `session` is not a live session.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_session_flush_stream(octocap_session_t* session);

/**
 * Resets temporal state (filter, person tracking), for example between takes.
 * @param[in] session A session.
 * @retval OCTOCAP_OK                   The session starts afresh at its next solve.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `session` is not a live session.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_session_reset(octocap_session_t* session);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/**
 * @name Live capture: cameras in, frames out, on library threads
 *
 * A live handle runs one capture thread per camera and one solving thread: each camera's newest picture is kept
 * (never a queue), pictures of the cameras are grouped by their grab time into frame sets (software sync: within a
 * tolerance, a camera that lags or drops is left out of that set rather than waited for), each set is detected and
 * solved as octocap_session_solve_images() does, and the newest solved frame is kept for the caller. Under
 * overload the oldest picture or frame is dropped and counted, so latency stays bounded.
 *
 * Cameras are given as strings, in calibration order: a V4L2 device ("/dev/video0" or "0"), a network camera
 * ("rtsp://...", "http://..." MJPEG), a video file (played at its own frame rate, as a camera would deliver it), a
 * folder of pictures (played at `picture_rate_hz`), or a remote camera "dds://NODE/CAMERA": the 2D keypoints a capture
 * node (octocap_node_*, below) detects in its pictures, received over DDS and assembled into frame sets exactly as
 * local pictures are (a hub whose cameras are all remote loads no detector). A network camera or device that breaks
 * is reopened with back-off while the others go on; a remote camera whose node falls silent for `read_timeout_ms` is
 * RECONNECTING until its keypoints come again; files and folders end.
 *
 * Threads: the control calls (set_detector, start, stop, destroy) from one thread at a time. The frame and status
 * queries may be called from any thread, also while the engine runs (an engine's game loop, a UI).
 */
/** @{ */

/** Opaque live capture. @since 1.0 */
typedef struct octocap_live_t octocap_live_t;

/** How a live capture trades accuracy for rate. @since 1.8 */
typedef int32_t octocap_live_quality_t;
/** Values of ::octocap_live_quality_t. @since 1.8 */
enum octocap_live_quality_values {
  OCTOCAP_QUALITY_GOVERNED = 0, /**< The rate governor: each set it picks a rung of a quality ladder from what the
                                     last sets cost, best first: the model on every view (at most the detector
                                     config's views_per_frame), on one view fewer, ... on one view (the others follow
                                     their people by optical flow), then the model card's lighter model (Thunder's:
                                     Lightning) on one view. It steps down within a few sets when sets cost more than
                                     the target period (or the latency budget) and back up after a hold of 2 s that
                                     doubles, up to 30 s, each time a step up had to be undone. octocap_live_stats_t
                                     says what it chose. Per view and crop detection only (the mosaic is one
                                     inference already). */
  OCTOCAP_QUALITY_MAX = 1       /**< Every set detected as the detector config says: the best accuracy, at whatever
                                     rate the host manages (latency stays bounded: sets are dropped, never queued). */
};

/** Live configuration. Fill with octocap_live_config_init() first. @since 1.0 */
typedef struct octocap_live_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_live_config_t); set by octocap_live_config_init(). */
  uint32_t sync_tolerance_us;    /**< Pictures within this of a set's time belong to it. 0 (default): half a frame period
                                      of the slowest camera. */
  uint32_t max_wait_us;          /**< A set goes out without a camera that has been silent this long.
                                      0 (default): 1.5 frame periods of the slowest camera (its measured rate when it delivers slower than it says). */
  uint32_t open_timeout_ms;      /**< Opening a camera gives up after this. Default 5000. */
  uint32_t read_timeout_ms;      /**< A live camera silent this long is broken and reopened. Default 3000. */
  uint32_t reconnect_max_ms;     /**< Longest back-off between reopen attempts (it starts at 100 ms). Default 2000. */
  float picture_rate_hz;         /**< Rate of picture-folder cameras. Default 30. */
  /* 1.1 */
  uint32_t remote_domain_id;     /**< DDS domain of remote cameras' keypoints. Default 0. @since 1.1 */
  char remote_topic[OCTOCAP_NAME_CAPACITY]; /**< Their topic base name ("<name>_keypoints2d"). Default "octocap".
                                      @since 1.1 */
  /* 1.8 */
  octocap_live_quality_t quality; /**< ::OCTOCAP_QUALITY_GOVERNED (default): hold target_fps within the latency budget,
                                      choosing each set how much detection it gets; ::OCTOCAP_QUALITY_MAX: every set
                                      gets the detector config's detection, however long it takes. @since 1.8 */
  float target_fps;              /**< Sets a second the governor holds. 0 (default): the slowest camera's rate.
                                      @since 1.8 */
  uint32_t latency_budget_ms;    /**< Grab of a set's oldest picture to its frame, that the governor keeps sets
                                      within (collection counts). Default 100; 10 .. 10000. @since 1.8 */
  /* 1.10 */
  char remote_security[OCTOCAP_PATH_CAPACITY]; /**< "" (default): remote cameras' keypoints are read over plain DDS.
                                      A keystore identity folder (role HUB): they are read over DDS Security, from
                                      nodes of the same keystore only. @since 1.10 */
} octocap_live_config_t;

/**
 * Fills the first `struct_size` bytes of `cfg` with defaults. Call it through octocap_live_config_init().
 * @param[out] cfg         The config to fill, `struct_size` bytes of it.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_live_config_t) of its header.
 * @retval OCTOCAP_OK                     `cfg` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no released size of the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_config_defaults(octocap_live_config_t* cfg, uint32_t struct_size);
/**
 * Fills `cfg` with this library's defaults; inline, so it never writes past the caller's struct.
 * @param[out] cfg The config to fill.
 * @since 1.0
 */
static inline void octocap_live_config_init(octocap_live_config_t* cfg) {
  (void)octocap_live_config_defaults(cfg, (uint32_t)sizeof *cfg);
}

/** Figures of a live capture. `struct_size` is set by the caller. Times are means over the frames solved so far.
 *  @since 1.0 */
typedef struct octocap_live_stats_t {
  uint32_t struct_size;          /**< Set by the caller to sizeof(octocap_live_stats_t). */
  uint32_t running;              /**< 1 between start and stop (or the end of every camera). */
  uint32_t finished;             /**< 1 when every camera ended (files and folders played out). */
  uint32_t camera_count;         /**< Cameras of the capture (the calibration's). */
  uint64_t frame_sets;           /**< Frame sets solved. */
  uint64_t frames_with_person;   /**< Of those, the ones in which a person was solved. */
  uint64_t sets_incomplete;      /**< Sets that went out without every camera. */
  uint64_t frames_not_taken;     /**< Solved frames replaced by a newer one before octocap_live_take_frame(). */
  float fps;                     /**< Solved frames per second (smoothed). */
  float capture_ms;              /**< Image collection: the set's oldest picture grabbed -> its solve starts. */
  float detect_ms;               /**< 2D detection. */
  float solve_ms;                /**< 3D solve, filter, rig and the session's outputs (DDS, VMC). */
  float publish_ms;              /**< Handing the frame over. */
  float latency_p50_ms;          /**< Grab of the oldest picture -> frame available, median of the last 1000 frames. */
  float latency_p99_ms;          /**< ... 99th percentile. */
  /* 1.2 */
  uint64_t sets_recorded;        /**< Frame sets written by the recording (octocap_live_set_recording()). @since 1.2 */
  uint64_t recording_pictures_dropped; /**< Of those, sets whose pictures were left out: the disk was behind (their
                                      keypoints and times are there; every camera's pictures of a set go together).
                                      @since 1.2 */
  /* 1.6 */
  uint32_t failed;               /**< 1: the engine stopped on an error it cannot go on from, said in last_error: a
                                      camera whose pictures have another aspect ratio than its calibration (another
                                      camera, or the cameras given in another order). `finished` is 1 too; call
                                      octocap_live_stop() as always. @since 1.6 */
  char last_error[OCTOCAP_ERROR_TEXT_CAPACITY]; /**< The last error ("" none): what failed the engine, a frame set
                                      that could not be solved (the engine goes on), the recording's write error.
                                      @since 1.6 */
  /* 1.8 */
  uint32_t quality_rung;         /**< The governor's rung for the last set, 0 the best (::OCTOCAP_QUALITY_GOVERNED).
                                      @since 1.8 */
  uint32_t quality_rungs;        /**< Rungs of its ladder; 0: not governed (::OCTOCAP_QUALITY_MAX, the mosaic, or
                                      every camera detected on a capture node). @since 1.8 */
  uint32_t views_detected;       /**< Views the network ran on in the last set (the others followed by optical flow;
                                      a view that lost its person is detected whatever the rung). @since 1.8 */
  float target_fps;              /**< The rate the governor holds (0: not governed). @since 1.8 */
  float budget_used;             /**< Smoothed cost of the last sets over what a set may cost (the target period, or
                                      less where the latency budget is tighter); above 1 the governor steps down.
                                      @since 1.8 */
  uint32_t rung_changes;         /**< Times the governor changed rung since start. @since 1.8 */
  char model[OCTOCAP_NAME_CAPACITY]; /**< The model card's name of the network that ran the last set ("" none).
                                      @since 1.8 */
  /* 1.13 */
  uint32_t views_in_set;         /**< Cameras the last set held (a picture, or a capture node's keypoints): camera_count
                                      for a complete set, fewer where a camera's picture missed it (sets_incomplete).
                                      `views_detected` counts among these. It takes what was the struct's end padding,
                                      so its size is unchanged: a 1.8-1.12 library leaves it as the caller set it.
                                      @since 1.13 */
} octocap_live_stats_t;

/** State of one camera. @since 1.0 */
typedef int32_t octocap_camera_state_t;
/** Values of ::octocap_camera_state_t. @since 1.0 */
enum octocap_camera_state_values {
  OCTOCAP_CAMERA_STOPPED = 0,      /**< Not started, or stopped. */
  OCTOCAP_CAMERA_CONNECTING = 1,   /**< Being opened. */
  OCTOCAP_CAMERA_STREAMING = 2,    /**< Delivering pictures (or, remote, keypoints). */
  OCTOCAP_CAMERA_RECONNECTING = 3, /**< A live camera broke; it is being reopened with back-off. */
  OCTOCAP_CAMERA_ENDED = 4,        /**< A file or folder played out. */
  OCTOCAP_CAMERA_FAILED = 5        /**< It cannot go on (last_error says why). */
};

/** One camera's figures. `struct_size` is set by the caller. @since 1.0 */
typedef struct octocap_camera_status_t {
  uint32_t struct_size;          /**< Set by the caller to sizeof(octocap_camera_status_t). */
  octocap_camera_state_t state;  /**< Where the camera is: ::octocap_camera_state_values. */
  uint64_t grabbed;              /**< Pictures read. */
  uint64_t used;                 /**< Pictures that went into a frame set. */
  uint64_t dropped;              /**< Pictures replaced by a newer one before a set took them, or too old for any set. */
  uint64_t reconnects;           /**< Times a broken live camera was reopened. */
  float fps;                     /**< Pictures per second read (smoothed). */
  float nominal_fps;             /**< What the camera says it delivers (0 when it does not say). */
  char name[OCTOCAP_NAME_CAPACITY]; /**< The calibration's name of this camera (a node's own name of it, for a node). */
  /* 1.1 */
  float clock_offset_ms;         /**< Remote cameras: how far behind their capture time (less the node's processing)
                                      keypoints arrive, the least of the last few hundred: network transit plus how far
                                      the node's clock lags this host's. Frame sets are matched on capture times
                                      corrected by it. Tens of ms or more, or negative: the clocks disagree (NTP/PTP).
                                      0 for local cameras. @since 1.1 */
  /* 1.4 */
  uint32_t stream_clock;         /**< 1: this camera's capture times come from its stream's own timestamps (RTP for
                                      RTSP), trusted once the stream and host clocks held steady for two seconds; 0:
                                      from when the host grabbed each picture (files, sources without timestamps, a
                                      stream's first seconds and after a reconnect), late by however long decoding
                                      took on a busy host, so a set may pair pictures of different instants.
                                      @since 1.4 */
  /* 1.6 */
  char last_error[OCTOCAP_ERROR_TEXT_CAPACITY]; /**< Why the camera last failed to open or broke ("" never): refused,
                                      not found, timed out, not a picture. Kept after it reconnected. @since 1.6 */
  /* 1.7 */
  uint64_t bad_pictures;         /**< Pictures received but left out because they could not be decoded (a corrupt
                                      JPEG, a part that is not a picture): the camera goes on, one bad picture does not
                                      end its connection. MJPEG over HTTP cameras count them; other cameras report 0.
                                      @since 1.7 */
} octocap_camera_status_t;

/**
 * Creates a live capture: `camera_count` camera strings in calibration order (see above), a session config (the
 * solve, and its DDS / VMC outputs) and a calibration (copied). Nothing is opened yet.
 * @param[in]  cfg          A live config filled with octocap_live_config_init() first.
 * @param[in]  session_cfg  A session config filled with octocap_session_config_init() first.
 * @param[in]  calib        The cameras' calibration, copied.
 * @param[in]  cameras      `camera_count` camera strings, in calibration order.
 * @param[in]  camera_count The calibration's camera count.
 * @param[out] out          The new live capture (NULL on failure); destroy it with octocap_live_destroy().
 * @retval OCTOCAP_OK                      `*out` is a new live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `cfg`, `session_cfg`, `out`, `cameras` or a camera string is NULL, an
 *                                         unknown URL scheme, a bad dds:// name, a bad config (the live config's
 *                                         or, as for octocap_session_create(), the session's), or a remote_security
 *                                         identity refused so (expired, not signed by its CA) or whose role may not
 *                                         read keypoints.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE       A config's struct_size is no released size.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH   Not as many cameras as the calibration has.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  The calibration has fewer than 2 cameras.
 * @retval OCTOCAP_ERROR_IO                A file, folder or device that does not exist (named), the DDS participant
 *                                         of remote cameras could not be made, or a security file is missing.
 * @retval OCTOCAP_ERROR_PARSE             A security file is not what it should be.
 * @retval OCTOCAP_ERROR_UNSUPPORTED       Remote cameras, streaming or VMC output in a build without DDS.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     The capture could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_create(const octocap_live_config_t* cfg,
                                                 const octocap_session_config_t* session_cfg,
                                                 const octocap_calibration_t* calib, const char* const* cameras,
                                                 uint32_t camera_count, octocap_live_t** out);
/**
 * Sets the detector (loaded now) before start; without it the default detector is loaded at start.
 * @param[in] live A live capture, not running.
 * @param[in] cfg  A detector config filled with octocap_detector_config_init() first.
 * @retval OCTOCAP_OK                     The detector is loaded.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL, the capture is running, or as for
 *                                        octocap_session_set_detector().
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_IO               As for octocap_detector_create(): a missing model or card.
 * @retval OCTOCAP_ERROR_PARSE            As for octocap_detector_create(): a malformed card or model.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      As for octocap_detector_create().
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The network could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_set_detector(octocap_live_t* live, const octocap_detector_config_t* cfg);
/**
 * Per camera (camera_count values, calibration order), how many microseconds late it delivers its pictures
 * (a network camera's encoder and transport, measured or from octocap sync): subtracted from its grab times before
 * frame sets are matched. Before start.
 * @param[in] live         A live capture, not running.
 * @param[in] offsets_us   `camera_count` offsets, -10 s .. +10 s each.
 * @param[in] camera_count The capture's camera count.
 * @retval OCTOCAP_OK                     The offsets are set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT NULL `offsets_us`, a wrong count, an offset beyond +-10 s, or the capture is
 *                                        running.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_set_latency_offsets(octocap_live_t* live, const int32_t* offsets_us,
                                                              uint32_t camera_count);
/**
 * Records the next run (from octocap_live_start() to octocap_live_stop()) into the folder `directory`, so that the take
 * can be solved again offline (`octocap solve --keypoints DIR/keypoints --calibration DIR/calibration.toml`) or
 * detected again (`--images DIR/images`). Every frame set the engine solves is written:
 *
 *     DIR/calibration.toml                                  the calibration the capture ran with
 *     DIR/keypoints/NN_<camera>_json/<camera>_<set>_keypoints.json   OpenPose JSON: the 2D people the set was
 *                                                           solved from, calibration pixels (none: camera absent)
 *     DIR/images/NN_<camera>/<set>.jpg                      the pictures (black: camera absent from the set)
 *     DIR/timestamps.csv                                    set,time_us,pictures,<camera>_us,... capture times on
 *                                                           the host's monotonic clock (empty: absent)
 *
 * NN is the camera's place in the calibration (01, 02, ...). Writing runs on a thread of its own behind a short
 * queue: when the disk is behind, a set's pictures are left out (counted in octocap_live_stats_t), never its keypoints.
 * Cameras detected on a capture node have keypoints only. `directory` NULL or "" turns recording off. Before start.
 * octocap_live_start() fails with IO when the folder cannot be made or already holds a take.
 * @param[in] live      A live capture, not running.
 * @param[in] directory The take's folder, or NULL or "" for no recording.
 * @retval OCTOCAP_OK                     The next run is recorded (or not, for NULL or "").
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT The capture is running.
 * @since 1.2
 */
OCTOCAP_API octocap_result_t octocap_live_set_recording(octocap_live_t* live, const char* directory);
/**
 * Loads the detector if needed, opens every camera (IO naming the first that cannot be opened; none stays open) and
 * starts the threads.
 * @param[in] live A live capture, not running.
 * @retval OCTOCAP_OK                     The capture runs.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT Already running, or the default detector's config is refused.
 * @retval OCTOCAP_ERROR_IO               A camera cannot be opened (named; none stays open), a remote camera's node
 *                                        sends nothing, the recording folder cannot be made or already holds a
 *                                        take, or a missing model or card.
 * @retval OCTOCAP_ERROR_PARSE            A malformed model or card.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      The detector's runtime is not in this build (as for
 *                                        octocap_detector_create()).
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed (a network, a picture decoder).
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_start(octocap_live_t* live);
/**
 * Stops the threads and closes the cameras; frames taken stay valid. Stopping a stopped capture is OK.
 * @param[in] live A live capture.
 * @retval OCTOCAP_OK                   Stopped; a recording is on disk.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `live` is not a live capture.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_stop(octocap_live_t* live);
/**
 * Stops (if running) and destroys; NULL is accepted.
 * @param[in] live A live capture, or NULL.
 * @since 1.0
 */
OCTOCAP_API void octocap_live_destroy(octocap_live_t* live);
/**
 * Takes the newest solved frame not taken before, waiting up to `timeout_ms` (0: do not wait); the caller releases
 * it.
 * @param[in]  live       A live capture.
 * @param[in]  timeout_ms Longest wait, milliseconds; 0 or less: do not wait.
 * @param[out] out        The new frame handle, or NULL when none came.
 * @retval OCTOCAP_OK                     `*out` is a new frame.
 * @retval OCTOCAP_STATUS_TIMEOUT         None came in time, `*out` = NULL (also once the capture stopped or finished).
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The frame handle could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_take_frame(octocap_live_t* live, int32_t timeout_ms, octocap_frame_t** out);
/**
 * The newest solved frame, taken or not (an engine reading once per game frame).
 * @param[in]  live A live capture.
 * @param[out] out  The new frame handle (NULL on failure).
 * @retval OCTOCAP_OK                     `*out` is a new frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solved frame.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The frame handle could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_get_frame(const octocap_live_t* live, octocap_frame_t** out);
/**
 * The capture's figures (`out->struct_size` set by the caller).
 * @param[in]     live A live capture.
 * @param[in,out] out  Its struct_size set by the caller (any released header's size); the rest, up to that size,
 *                     is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than 1.0's struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_get_stats(const octocap_live_t* live, octocap_live_stats_t* out);
/**
 * Camera `index`'s figures (`out->struct_size` set by the caller).
 * @param[in]     live  A live capture.
 * @param[in]     index 0 .. camera count - 1.
 * @param[in,out] out   Its struct_size set by the caller (any released header's size); the rest, up to that size,
 *                      is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `live` is not a live capture.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `index` is out of range.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than 1.0's struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_live_get_camera_status(const octocap_live_t* live, uint32_t index,
                                                            octocap_camera_status_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Capture nodes: more cameras than one machine can detect
 *
 * A node runs some cameras on one machine: each camera is detected on its own thread, at wall-clock ticks every node
 * shares (a slow detector skips pictures, counted, never queues them), and its 2D keypoints, stamped with their capture time on the
 * node's wall clock, are published over Cyclone DDS on "<topic>_keypoints2d". A hub takes them as cameras
 * "dds://NODE/CAMERA" of a live capture and solves them with its other cameras. Node and hub clocks must agree to
 * well under a frame period (NTP on a LAN is a millisecond or so; PTP better): the hub reports each remote camera's
 * measured offset (octocap_camera_status_t.clock_offset_ms). Needs a build with DDS (UNSUPPORTED otherwise).
 *
 * Threads: as for a live capture.
 */
/** @{ */

/** Opaque capture node. @since 1.1 */
typedef struct octocap_node_t octocap_node_t;

/** Capture node configuration. Fill with octocap_node_config_init() first. @since 1.1 */
typedef struct octocap_node_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_node_config_t); set by octocap_node_config_init(). */
  char name[OCTOCAP_NAME_CAPACITY]; /**< The NODE of dds://NODE/CAMERA: 1 to 31 bytes, no '/'. Default "node1". */
  uint32_t domain_id;            /**< DDS domain. Default 0. */
  char topic[OCTOCAP_NAME_CAPACITY]; /**< Topic base name ("<name>_keypoints2d"). Default "octocap". */
  uint32_t open_timeout_ms;      /**< As in ::octocap_live_config_t. Default 5000. */
  uint32_t read_timeout_ms;      /**< Default 3000. */
  uint32_t reconnect_max_ms;     /**< Default 2000. */
  float picture_rate_hz;         /**< Default 30. */
  float detect_rate_hz;          /**< Detections per second and camera, at wall-clock ticks every node shares (the
                                      pictures nearest k / rate s since 1970), so that a hub's frame sets find views of
                                      one instant; a tick the detector cannot keep up with is skipped. 0 (default): the
                                      fastest of 60, 30, 20, 15, 12, 10, 6, 5, 4, 3, 2, 1 it keeps up with (rates that
                                      meet at common ticks); give every node the same rate for whole sets at it. */
  /* 1.10 */
  char security[OCTOCAP_PATH_CAPACITY]; /**< "" (default): plain DDS. A keystore identity folder (role NODE): the
                                      keypoints are published over DDS Security, for hubs of the same keystore only.
                                      @since 1.10 */
} octocap_node_config_t;

/**
 * Fills the first `struct_size` bytes of `cfg` with defaults. Call it through octocap_node_config_init().
 * @param[out] cfg         The config to fill, `struct_size` bytes of it.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_node_config_t) of its header.
 * @retval OCTOCAP_OK                     `cfg` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no released size of the struct.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_config_defaults(octocap_node_config_t* cfg, uint32_t struct_size);
/**
 * Fills `cfg` with this library's defaults; inline, so it never writes past the caller's struct.
 * @param[out] cfg The config to fill.
 * @since 1.1
 */
static inline void octocap_node_config_init(octocap_node_config_t* cfg) {
  (void)octocap_node_config_defaults(cfg, (uint32_t)sizeof *cfg);
}

/** A node's figures. `struct_size` is set by the caller. @since 1.1 */
typedef struct octocap_node_stats_t {
  uint32_t struct_size;          /**< Set by the caller to sizeof(octocap_node_stats_t). */
  uint32_t running;              /**< 1 between start and stop. */
  uint32_t finished;             /**< 1 when every camera ended (files and folders played out). */
  uint32_t camera_count;         /**< Cameras of the node. */
  uint64_t published;            /**< Views published, all cameras together. */
  uint64_t with_person;          /**< Of those, views with at least one person. */
  float detect_ms;               /**< 2D detection per view, mean. */
  float processing_ms;           /**< Grab -> published, mean. */
  uint32_t readers;              /**< Hubs reading the keypoints now. */
} octocap_node_stats_t;

/**
 * Creates a capture node over `camera_count` cameras (any camera string of a live capture but "dds://"), named by
 * `names` (the CAMERA of dds://NODE/CAMERA; NULL: "cam01", "cam02", ...). Nothing is opened yet.
 * @param[in]  cfg          A node config filled with octocap_node_config_init() first.
 * @param[in]  cameras      `camera_count` camera strings.
 * @param[in]  names        `camera_count` names (1 to 31 bytes, no '/', all different), or NULL.
 * @param[in]  camera_count 1 or more.
 * @param[out] out          The new node (NULL on failure); destroy it with octocap_node_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new node.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg`, `cameras`, `out` or a string is NULL, no camera, bad names, a dds://
 *                                        camera or an unknown scheme, a config value out of range.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_IO               A file, folder or device that does not exist.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      No DDS in this build.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The node could not be allocated.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_create(const octocap_node_config_t* cfg, const char* const* cameras,
                                                 const char* const* names, uint32_t camera_count, octocap_node_t** out);
/**
 * Sets the detector of every camera (loaded at start) before start.
 * @param[in] node A node, not running.
 * @param[in] cfg  A detector config filled with octocap_detector_config_init() first.
 * @retval OCTOCAP_OK                     The config is kept for start.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `node` is not a live node.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL, a config value is out of range, or the node is running.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_set_detector(octocap_node_t* node, const octocap_detector_config_t* cfg);
/**
 * Loads the detectors, opens every camera (IO naming one that cannot be opened), starts publishing.
 * @param[in] node A node, not running.
 * @retval OCTOCAP_OK                     The node publishes.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `node` is not a live node.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT Already running, a detector the model does not fit (as for
 *                                        octocap_detector_create()), or a security identity refused so (expired,
 *                                        not signed by its CA) or whose role may not publish keypoints.
 * @retval OCTOCAP_ERROR_IO               A camera that cannot be opened (named), the DDS participant could not be
 *                                        made, a missing security file, model or card.
 * @retval OCTOCAP_ERROR_PARSE            A security file, model or card that is not what it should be.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      The detector's runtime is not in this build.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed (a network, a picture decoder).
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_start(octocap_node_t* node);
/**
 * Stops publishing and closes the cameras. Stopping a stopped node is OK.
 * @param[in] node A node.
 * @retval OCTOCAP_OK                   Stopped.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `node` is not a live node.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_stop(octocap_node_t* node);
/**
 * Stops (if running) and destroys; NULL is accepted.
 * @param[in] node A node, or NULL.
 * @since 1.1
 */
OCTOCAP_API void octocap_node_destroy(octocap_node_t* node);
/**
 * The node's figures (`out->struct_size` set by the caller).
 * @param[in]     node A node.
 * @param[in,out] out  Its struct_size set by the caller; the rest is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `node` is not a live node.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than the struct.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_get_stats(const octocap_node_t* node, octocap_node_stats_t* out);
/**
 * Camera `index`'s figures, `name` being the node's name of it (`out->struct_size` set by the caller).
 * @param[in]     node  A node.
 * @param[in]     index 0 .. camera count - 1.
 * @param[in,out] out   Its struct_size set by the caller (any released header's size); the rest, up to that size,
 *                      is filled.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `node` is not a live node.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `index` is out of range.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `out->struct_size` is smaller than 1.0's struct.
 * @since 1.1
 */
OCTOCAP_API octocap_result_t octocap_node_get_camera_status(const octocap_node_t* node, uint32_t index,
                                                            octocap_camera_status_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Streaming: receiving skeletons over Cyclone DDS
 *
 * A session with `stream_enable` publishes every frame on two topics: "<topic>_definition" (the skeleton
 * definition: layout, keypoint and joint names, bones; reliable, transient-local, so a late joiner always has
 * it) and, per frame, "<topic>_pose" (one person) or, for a session whose max_people is not 1, "<topic>_people"
 * (everyone of the frame in one sample, with their ids: a reader never mixes people of two frames). A subscriber
 * reads both. The IDL (sdk/src/stream/idl/octocap_stream.idl) is the wire's reference. Publishing never blocks the solve: frames go to a queue that a
 * library thread writes; when it is full the oldest frame is dropped. A subscriber, in this process or on
 * another machine, hands out the same frames as a local session. Cyclone is configured as usual through the
 * CYCLONEDDS_URI environment variable (network interface, multicast, peers).
 */
/** @{ */

/** Opaque stream subscriber. @since 0.2 */
typedef struct octocap_subscriber_t octocap_subscriber_t;

/** Subscriber configuration. Fill with octocap_subscriber_config_init() first. @since 0.2 */
typedef struct octocap_subscriber_config_t {
  uint32_t struct_size;          /**< sizeof(octocap_subscriber_config_t). */
  uint32_t domain_id;            /**< DDS domain. Default 0. */
  octocap_stream_qos_t qos;      /**< Must match the publisher's. Default ::OCTOCAP_QOS_LIVE. */
  uint32_t history_depth;        /**< RECORD: poses kept for this reader. Default 256. */
  uint32_t source_id;            /**< Only this source; 0 = any. Default 0. */
  char topic[OCTOCAP_NAME_CAPACITY]; /**< Default "octocap". */
  /* 1.10 */
  char security[OCTOCAP_PATH_CAPACITY]; /**< "" (default): plain DDS. A keystore identity folder (role VIEWER or
                                      HUB): the stream is read over DDS Security, from publishers of the same keystore
                                      only. The publisher and the subscriber are secured alike or they never meet.
                                      @since 1.10 */
} octocap_subscriber_config_t;

/** Counters of a subscription. @since 0.2 */
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

/**
 * Fills the first `struct_size` bytes of `cfg` with defaults and sets its struct_size. Call it through
 * octocap_subscriber_config_init().
 * @param[out] cfg         The config to fill, `struct_size` bytes of it.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_subscriber_config_t) of its header.
 * @retval OCTOCAP_OK                     `cfg` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no released size of the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_subscriber_config_defaults(octocap_subscriber_config_t* cfg, uint32_t struct_size);
/**
 * Fills `cfg` with this library's defaults; inline, so it never writes past the caller's struct.
 * @param[out] cfg The config to fill.
 * @since 0.2 (an exported function until 1.0, inline over octocap_subscriber_config_defaults() since)
 */
static inline void octocap_subscriber_config_init(octocap_subscriber_config_t* cfg) {
  (void)octocap_subscriber_config_defaults(cfg, (uint32_t)sizeof *cfg);
}
/**
 * Joins a stream.
 * @param[in]  cfg A config filled with octocap_subscriber_config_init() first.
 * @param[out] out The new subscriber (NULL on failure); destroy it with octocap_subscriber_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new subscriber.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `cfg` or `out` is NULL, a domain above 232, an unknown QoS, a history depth
 *                                        outside 1..100000, a topic that is not letters, digits and '_', an
 *                                        unterminated security path, or an identity whose role may not read the
 *                                        stream (or that expired, or is not signed by its keystore's CA).
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `cfg->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_IO               The DDS participant could not be made, or a security file is missing.
 * @retval OCTOCAP_ERROR_PARSE            A security file is not what it should be.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      A build without DDS.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The subscriber could not be allocated.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_subscriber_create(const octocap_subscriber_config_t* cfg,
                                                       octocap_subscriber_t** out);
/**
 * Leaves the stream; NULL is accepted.
 * @param[in] sub A subscriber, or NULL.
 * @since 0.2
 */
OCTOCAP_API void octocap_subscriber_destroy(octocap_subscriber_t* sub);
/**
 * Takes the next pose in arrival order, waiting up to `timeout_ms` (0: do not wait), as a new frame handle the
 * caller releases. The subscriber keeps one thread's state: take from one thread at a time.
 * @param[in]  sub        A subscriber.
 * @param[in]  timeout_ms Longest wait, milliseconds; 0: do not wait.
 * @param[out] out        The new frame handle, or NULL when none arrived.
 * @retval OCTOCAP_OK                     `*out` is a new frame.
 * @retval OCTOCAP_STATUS_TIMEOUT         None arrived in time, `*out` = NULL.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The frame handle could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_subscriber_take_frame(octocap_subscriber_t* sub, int32_t timeout_ms,
                                                           octocap_frame_t** out);
/**
 * Counters: frames received and lost, publisher restarts, rejected samples.
 * @param[in]  sub A subscriber.
 * @param[out] out The counters.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_subscriber_get_stream_info(const octocap_subscriber_t* sub,
                                                                octocap_stream_info_t* out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Securing the network: a DDS Security keystore
 *
 * A plain DDS stream can be read by anyone on the network, and anyone can publish keypoints into a hub. A keystore
 * closes the network to everyone else: one certificate authority (CA) signs an identity per participant, a governance
 * (no unauthenticated participant joins; discovery, liveliness and every sample are encrypted) and each identity's
 * permissions, which follow its role:
 *
 *     octocap_keystore_create("studio", 3650);                                   CA + governance, once per studio
 *     octocap_keystore_add_identity("studio", "hub", OCTOCAP_ROLE_HUB, 365);     studio/hub/
 *     octocap_keystore_add_identity("studio", "booth1", OCTOCAP_ROLE_NODE, 365); studio/booth1/
 *     octocap_keystore_add_identity("studio", "unity", OCTOCAP_ROLE_VIEWER, 365);
 *
 * Each participant is then given its identity folder: `stream_security` (a session that streams),
 * `remote_security` (a live engine reading capture nodes), `security` (a node, a subscriber); `--dds-security
 * studio/hub` in the tools. Nothing else changes: CYCLONEDDS_URI configures the network as before. A participant
 * with no identity, or another keystore's, neither reads nor writes; one whose role does not cover a topic gets
 * INVALID_ARGUMENT naming the topic. The files are checked when a participant starts (IO: missing; PARSE: not what
 * they should be; INVALID_ARGUMENT: expired, not signed by the keystore's CA, a key that is not the certificate's).
 * The CA's private key (KEYSTORE/ca.key.pem) is needed only to add identities: keep it off the capture machines.
 * Made with OpenSSL (P-256 keys, SHA-256, S/MIME-signed XML, the layout Cyclone DDS's security plugins read); the
 * plugins (libdds_security_auth, _ac and _crypto) must be installed, as Debian's libddsc0debian does.
 * Since 1.10.
 */
/** @{ */

/** What an identity may do on the network: one of the OCTOCAP_ROLE_* values (an int32_t, as the other enumerated
 *  parameters, so that any value a caller passes is defined behaviour and refused with INVALID_ARGUMENT).
 *  @since 1.10 */
typedef int32_t octocap_security_role_t;
/** Values of ::octocap_security_role_t. @since 1.10 */
enum {
  OCTOCAP_ROLE_NODE = 0,        /**< Publishes 2D keypoints ("<topic>_keypoints2d"): a capture node. */
  OCTOCAP_ROLE_HUB = 1,         /**< Reads keypoints; publishes skeletons ("<topic>_definition", "_pose", "_people"):
                                     a live engine, a session that streams. */
  OCTOCAP_ROLE_VIEWER = 2       /**< Reads skeletons: a subscriber (a viewer, a game). */
};

/**
 * Makes a keystore in `dir` (created if missing; readable by its owner only): KEYSTORE/ca.pem, ca.key.pem,
 * governance.xml and its signed governance.p7s, valid for `valid_days` (1 .. 36500).
 * @param[in] dir        The keystore's folder.
 * @param[in] valid_days How long the CA and the governance are valid, 1 .. 36500 days.
 * @retval OCTOCAP_OK                     The keystore is made.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `dir` is NULL, a folder that holds a keystore already (whose identities a
 *                                        new CA would orphan), or days out of range.
 * @retval OCTOCAP_ERROR_IO               The folder or a file cannot be made or written.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    OpenSSL could not allocate.
 * @since 1.10
 */
OCTOCAP_API octocap_result_t octocap_keystore_create(const char* dir, uint32_t valid_days);
/**
 * Adds identity `name` (1 to 64 letters, digits, '-', '_', '.') with `role` to the keystore `dir`: DIR/NAME/cert.pem
 * (subject "CN=NAME,O=octocap", signed by the CA), key.pem (owner-only), permissions.xml and permissions.p7s, valid
 * for `valid_days`.
 * @param[in] dir        A keystore made by octocap_keystore_create().
 * @param[in] name       The identity's name.
 * @param[in] role       An ::octocap_security_role_t value.
 * @param[in] valid_days How long the certificate and the permissions are valid, 1 .. 36500 days.
 * @retval OCTOCAP_OK                     DIR/NAME is made.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `dir` or `name` is NULL, a bad name, an identity that exists, an unknown
 *                                        role, or days out of range.
 * @retval OCTOCAP_ERROR_IO               No keystore in `dir` (its CA files cannot be read), or a file cannot be
 *                                        written.
 * @retval OCTOCAP_ERROR_PARSE            The keystore's CA files are not PEM.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    OpenSSL could not allocate.
 * @since 1.10
 */
OCTOCAP_API octocap_result_t octocap_keystore_add_identity(const char* dir, const char* name,
                                                           octocap_security_role_t role, uint32_t valid_days);
/**
 * Checks an identity folder as a participant would before it joins, and writes its role (NULL allowed). Its errors
 * are those of a participant's start, each naming the file and the cause.
 * @param[in]  identity_dir An identity folder (KEYSTORE/NAME).
 * @param[out] role         Its role, or NULL.
 * @retval OCTOCAP_OK                     The identity would join; `*role` is set when given.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `identity_dir` is NULL, or a certificate or the permissions expired (or not
 *                                        valid yet), not signed by the keystore's CA, a key that is not the
 *                                        certificate's, or permissions granted to another subject.
 * @retval OCTOCAP_ERROR_IO               The folder or one of its files (or the keystore's) is missing.
 * @retval OCTOCAP_ERROR_PARSE            A file is not what it should be (not PEM, not signed S/MIME, no validity
 *                                        dates, a grant of no octocap role).
 * @since 1.10
 */
OCTOCAP_API octocap_result_t octocap_keystore_check_identity(const char* identity_dir, octocap_security_role_t* role);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Recordings on disk: OpenPose JSON folders (Pose2Sim layout) */
/** @{ */

/** Opaque OpenPose JSON recording: one sub-folder per camera (sorted by name), one file per frame (sorted).
 *  @since 0.1 */
typedef struct octocap_recording_t octocap_recording_t;

/**
 * Opens a folder of per-camera OpenPose JSON folders. Files are parsed lazily per frame; the folder
 * structure is checked here. `layout` AUTO detects it from the first file's keypoint count.
 * @param[in]  directory The recording's folder.
 * @param[in]  layout    The keypoints' layout, or ::OCTOCAP_LAYOUT_AUTO.
 * @param[out] out       The new recording (NULL on failure); destroy it with octocap_recording_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `directory` or `out` is NULL, or an unknown layout.
 * @retval OCTOCAP_ERROR_IO               Not a folder, or no camera sub-folder holding OpenPose .json files.
 * @retval OCTOCAP_ERROR_PARSE            A file read to detect the layout is malformed, or no file has a person.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The recording could not be allocated.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_open(const char* directory, octocap_layout_t layout,
                                                    octocap_recording_t** out);
/**
 * Destroys a recording; NULL is accepted.
 * @param[in] rec A recording, or NULL.
 * @since 0.1
 */
OCTOCAP_API void octocap_recording_destroy(octocap_recording_t* rec);
/**
 * Number of views (camera folders).
 * @param[in]  rec A recording.
 * @param[out] out The view count.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_view_count(const octocap_recording_t* rec, uint32_t* out);
/**
 * Number of frames (the smallest file count of the camera folders).
 * @param[in]  rec A recording.
 * @param[out] out The frame count.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_frame_count(const octocap_recording_t* rec, uint32_t* out);
/**
 * The layout in use (resolved when AUTO was given).
 * @param[in]  rec A recording.
 * @param[out] out The layout.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_layout(const octocap_recording_t* rec, octocap_layout_t* out);
/**
 * Name of camera folder `view` (such as "cam1_json"), copied into `out` (capacity bytes incl. NUL).
 * @param[in]  rec      A recording.
 * @param[in]  view     0 .. view count - 1.
 * @param[out] out      `capacity` bytes for the name.
 * @param[in]  capacity Bytes `out` holds, NUL included.
 * @retval OCTOCAP_OK                     `out` holds the name.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `view` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is short (the message says how many bytes the name needs).
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_view_name(const octocap_recording_t* rec, uint32_t view, char* out,
                                                         uint32_t capacity);

/**
 * Reads frame `frame`: fills people_per_view (view_count entries) and the flat keypoints array in the
 * layout of octocap_session_solve_keypoints. With keypoints == NULL only `keypoint_count` (total keypoints
 * needed) is written, and people_per_view when it is not NULL.
 * @param[in]  rec             A recording.
 * @param[in]  frame           0 .. frame count - 1.
 * @param[out] keypoints       `capacity` keypoints, or NULL to learn the count.
 * @param[in]  capacity        Keypoints `keypoints` holds.
 * @param[out] keypoint_count  The keypoints of the frame, all views and people together.
 * @param[out] people_per_view `view_count` counts (required with `keypoints`, else may be NULL).
 * @param[in]  view_count      The recording's view count.
 * @retval OCTOCAP_OK                     The counts are set, and `keypoints` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `keypoint_count` is NULL, `people_per_view` is NULL with `keypoints`, or
 *                                        `frame` is out of range.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH  `view_count` is not the recording's view count.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below `*keypoint_count`.
 * @retval OCTOCAP_ERROR_IO               A frame's file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE            A frame's file is malformed (named, with the fault).
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_recording_read_frame(octocap_recording_t* rec, uint32_t frame,
                                                          octocap_keypoint2d_t* keypoints, uint32_t capacity,
                                                          uint32_t* keypoint_count, uint32_t* people_per_view,
                                                          uint32_t view_count);

/**
 * Time offsets of unsynchronised cameras (phones, action cams, IP cameras started apart), from the person's own
 * motion: every pair of cameras measures its offset difference where their views agree best (median epipolar
 * distance of the best-agreeing pair of people per frame, every confident keypoint, sub-frame), and all pairs fix the
 * offsets together (weighted least squares). It needs
 * motion: a take where the person hardly moves leaves the cost flat (check `residual_px` against the calibration's
 * own error). `offsets_frames` (count = the views) gets, per camera, where its frame i was captured: (i + offset)
 * on the first camera's clock (0 for the first); `residual_px` (may be NULL) the distance there. Searches
 * +-max_offset_frames. The recording's own offsets (octocap_recording_set_sync) are ignored.
 * @param[in]  rec               A recording.
 * @param[in]  calib             Its cameras' calibration.
 * @param[in]  max_offset_frames The widest offset searched, 0 .. 100000 frames.
 * @param[out] offsets_frames    `count` offsets, frames.
 * @param[out] residual_px       `count` distances, pixels, or NULL.
 * @param[in]  count             The calibration's camera count.
 * @retval OCTOCAP_OK                      The offsets are set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `rec` or `calib` is not a live handle.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `offsets_frames` is NULL, or `max_offset_frames` is NaN or out of range.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH   `count`, or the recording's view count, is not the calibration's cameras.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  A camera never shares enough keypoints with the first.
 * @retval OCTOCAP_ERROR_IO                A frame's file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE             A frame's file is malformed.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     An allocation failed.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_recording_estimate_sync(const octocap_recording_t* rec,
                                                             const octocap_calibration_t* calib,
                                                             double max_offset_frames, double* offsets_frames,
                                                             float* residual_px, uint32_t count);
/**
 * From now on octocap_recording_read_frame(rec, f, ...) gives each view at its own frame f - offset, interpolated
 * between its two nearest frames (the first camera's clock); NULL clears.
 * @param[in] rec            A recording.
 * @param[in] offsets_frames `count` offsets (as octocap_recording_estimate_sync() gives), or NULL for none.
 * @param[in] count          The recording's view count.
 * @retval OCTOCAP_OK                     The offsets apply from the next read.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `rec` is not a live recording.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT A wrong count, or an offset that is NaN, infinite or beyond a million frames.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_recording_set_sync(octocap_recording_t* rec, const double* offsets_frames,
                                                        uint32_t count);
/**
 * Writes offsets as a sync TOML (`rate`, `[offsets_frames]` by the calibration's camera names).
 * @param[in] path           The file to write.
 * @param[in] rate_hz        The frame rate the offsets count in, > 0 and at most 100000.
 * @param[in] calib          The calibration naming the cameras.
 * @param[in] offsets_frames `count` offsets, frames.
 * @param[in] count          The calibration's camera count.
 * @retval OCTOCAP_OK                     The file is written.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` or `offsets_frames` is NULL, an offset is NaN, infinite or beyond a
 *                                        million frames, or the rate is not > 0 and at most 100000 (what
 *                                        octocap_sync_load() reads back).
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH  `count` is not the calibration's camera count.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened or written.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_sync_save(const char* path, double rate_hz, const octocap_calibration_t* calib,
                                               const double* offsets_frames, uint32_t count);
/**
 * Reads a sync TOML into `offsets_frames` (count = the calibration's cameras, matched by name) and `rate_hz` (may be
 * NULL).
 * @param[in]  path           A sync TOML, as octocap_sync_save() writes.
 * @param[in]  calib          The calibration whose camera names the offsets are matched by.
 * @param[out] offsets_frames `count` offsets, frames.
 * @param[in]  count          The calibration's camera count.
 * @param[out] rate_hz        The file's frame rate, or NULL.
 * @retval OCTOCAP_OK                     The offsets are set.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` or `offsets_frames` is NULL.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `calib` is not a live calibration.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH  `count` is not the calibration's camera count.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE            Malformed, or a camera of the calibration missing from it.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_sync_load(const char* path, const octocap_calibration_t* calib,
                                               double* offsets_frames, uint32_t count, double* rate_hz);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Calibrating (stage 1): intrinsics from a board, extrinsics from a person */
/** @{ */

/**
 * Intrinsics and distortion of one camera from a folder of board images. `board` is
 * "checkerboard:COLSxROWS:SQUARE_M" (inner corners, metres) or "charuco:COLSxROWS:SQUARE_M:MARKER_M[:DICT]"
 * (squares; dictionary DICT_6X6_250 unless named). Unreadable, blurred and partial views (for ChArUco: fewer
 * than a third of the corners) are rejected and logged; at least 3 good views are needed. The camera's pose in `out` is identity.
 * `overlay_png` (may be NULL): a PNG of the first good view with detected and reprojected corners drawn.
 * @param[in]  images_dir      A folder of board images (png, jpg, bmp, tif).
 * @param[in]  board           The board, as above.
 * @param[out] out             The camera: size, intrinsics, distortion; identity pose; the folder's name.
 * @param[out] rms_px          The RMS reprojection error, pixels, or NULL.
 * @param[out] images_used     Images that went into the solve, or NULL.
 * @param[out] images_rejected Images rejected, or NULL.
 * @param[in]  overlay_png     The overlay's path, or NULL for none.
 * @retval OCTOCAP_OK                      `*out` is the camera.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `images_dir`, `board` or `out` is NULL, or `board` is no board spec (an
 *                                         unknown dictionary, too few squares or corners, sizes <= 0).
 * @retval OCTOCAP_ERROR_IO                Not a folder, no image files in it, or the overlay cannot be written.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  Fewer than 3 good views.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     An allocation failed.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_calibration_solve_intrinsics(const char* images_dir, const char* board,
                                                                  octocap_camera_t* out, float* rms_px,
                                                                  uint32_t* images_used, uint32_t* images_rejected,
                                                                  const char* overlay_png);

/** Options of octocap_calibration_solve_extrinsics(). Fill with octocap_extrinsics_options_init() first.
 *  @since 0.3 */
typedef struct octocap_extrinsics_options_t {
  uint32_t struct_size;          /**< sizeof(octocap_extrinsics_options_t). */
  float person_height_m;         /**< Scale from the person's standing height, or (when > 0) ... */
  float camera_distance_m;       /**< ... from the measured distance between two cameras: */
  int32_t distance_camera_a;     /**< first camera of that distance (index), */
  int32_t distance_camera_b;     /**< second camera. */
  float min_confidence;          /**< Keypoints below are not used. Default 0.4. */
  uint32_t max_frames;           /**< More frames are subsampled evenly. Default 1500. */
  octocap_up_axis_t up_axis;     /**< World frame of the result: Y (default) or Z up. */
  uint32_t refine;               /**< 1: refine the given poses (a camera was nudged), keeping their world frame
                                      and scale; no height or distance needed. Default 0. */
} octocap_extrinsics_options_t;

/** What a calibration achieved. @since 0.3 */
typedef struct octocap_calibration_report_t {
  uint32_t camera_count;         /**< Cameras solved: the entries of rms_px and observations that are set. */
  float rms_px[64];              /**< Per camera: RMS reprojection error of the inlier observations. */
  uint32_t observations[64];     /**< Per camera: inlier observations used. */
  uint32_t points;               /**< 3D points reconstructed. */
  uint32_t iterations;           /**< Bundle adjustment iterations. */
  float initial_rms_px;          /**< Before bundle adjustment. */
  float final_rms_px;            /**< After. */
} octocap_calibration_report_t;

/**
 * Fills the first `struct_size` bytes of `opt` with defaults and sets its struct_size. Call it through
 * octocap_extrinsics_options_init().
 * @param[out] opt         The options to fill, `struct_size` bytes of them.
 * @param[in]  struct_size The size of the caller's struct: sizeof(octocap_extrinsics_options_t) of its header.
 * @retval OCTOCAP_OK                     `opt` holds the defaults.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `opt` is NULL.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE      `struct_size` is no released size of the struct.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_extrinsics_options_defaults(octocap_extrinsics_options_t* opt, uint32_t struct_size);
/**
 * Fills `opt` with this library's defaults; inline, so it never writes past the caller's struct.
 * @param[out] opt The options to fill.
 * @since 0.3 (an exported function until 1.0, inline over octocap_extrinsics_options_defaults() since)
 */
static inline void octocap_extrinsics_options_init(octocap_extrinsics_options_t* opt) {
  (void)octocap_extrinsics_options_defaults(opt, (uint32_t)sizeof *opt);
}

/**
 * Every camera's pose from a person moving through the volume: their 2D keypoints in `rec` (one folder per
 * camera, same order as `intrinsics`) are the common points. Pairwise essential matrix, cameras added by PnP,
 * bundle adjustment (Ceres) over all cameras and points; scale from the person's height or a camera distance;
 * world origin on the floor below the person, up along the person. Intrinsics and distortion are taken from
 * `intrinsics` (its poses are ignored). `report` may be NULL. Errors name disconnected camera groups,
 * degenerate motion and a missing scale.
 * @param[in]  intrinsics The cameras' intrinsics (2 to 64 cameras; with `opt->refine`, their poses too).
 * @param[in]  rec        The person's 2D keypoints, one folder per camera.
 * @param[in]  opt        Options filled with octocap_extrinsics_options_init() first.
 * @param[out] out        The new calibration (NULL on failure); destroy it with octocap_calibration_destroy().
 * @param[out] report     What the solve achieved, or NULL.
 * @retval OCTOCAP_OK                      `*out` is the new calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `opt` or `out` is NULL, an option is NaN or unknown, more than 64 cameras,
 *                                         no scale (neither height nor a distance of two different cameras),
 *                                         degenerate motion, too few frames of the whole or upright person, or (to
 *                                         refine) too few keypoints that agree with the given poses.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `intrinsics` or `rec` is not a live handle.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE       `opt->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH   The recording's camera folders are not the calibration's cameras.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  Fewer than 2 cameras, a camera that saw the person in too few frames, or
 *                                         camera groups that never see the person together (named).
 * @retval OCTOCAP_ERROR_IO                A keypoint file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE             A keypoint file is malformed.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     An allocation failed.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_calibration_solve_extrinsics(const octocap_calibration_t* intrinsics,
                                                                  octocap_recording_t* rec,
                                                                  const octocap_extrinsics_options_t* opt,
                                                                  octocap_calibration_t** out,
                                                                  octocap_calibration_report_t* report);

/**
 * Every camera's pose from a checkerboard seen by several cameras at once. `images_dir` holds one sub-folder per
 * camera (sorted, in calibration order); images with the same file name were taken at the same moment. The
 * board's square size sets the scale; the first image set's board lies on the floor and defines the world
 * (origin at its first inner corner, X along its columns, up along its normal). Only `opt->up_axis` is used.
 * @param[in]  intrinsics The cameras' intrinsics (2 to 64 cameras).
 * @param[in]  images_dir One sub-folder of board images per camera.
 * @param[in]  board      The board, as for octocap_calibration_solve_intrinsics().
 * @param[in]  opt        Options filled with octocap_extrinsics_options_init() first.
 * @param[out] out        The new calibration (NULL on failure); destroy it with octocap_calibration_destroy().
 * @param[out] report     What the solve achieved, or NULL.
 * @retval OCTOCAP_OK                      `*out` is the new calibration.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT  `images_dir`, `board`, `opt` or `out` is NULL, `board` is no board spec,
 *                                         an option is NaN or unknown, or more than 64 cameras.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE    `intrinsics` is not a live calibration.
 * @retval OCTOCAP_ERROR_STRUCT_SIZE       `opt->struct_size` is no released size.
 * @retval OCTOCAP_ERROR_CAMERA_MISMATCH   The camera sub-folders are not the calibration's cameras.
 * @retval OCTOCAP_ERROR_NOT_ENOUGH_VIEWS  Fewer than 2 cameras, no image set in which a camera saw the whole board,
 *                                         or cameras that never saw it together with the others (named).
 * @retval OCTOCAP_ERROR_IO                `images_dir` is not a folder.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY     An allocation failed.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_calibration_solve_extrinsics_boards(const octocap_calibration_t* intrinsics,
                                                                         const char* images_dir, const char* board,
                                                                         const octocap_extrinsics_options_t* opt,
                                                                         octocap_calibration_t** out,
                                                                         octocap_calibration_report_t* report);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/** @name Motion files: TRC (OpenSim/Pose2Sim) and CSV */
/** @{ */

/** Opaque writer of 3D keypoints, one row per frame. @since 0.1 */
typedef struct octocap_motion_writer_t octocap_motion_writer_t;

/** File formats of ::octocap_motion_writer_t. @since 0.1 */
typedef int32_t octocap_motion_format_t;
/** Values of ::octocap_motion_format_t. @since 0.1 */
enum octocap_motion_format_values {
  OCTOCAP_MOTION_TRC = 0, /**< OpenSim TRC, Y up (Z-up worlds are turned as Pose2Sim does), metres. */
  OCTOCAP_MOTION_CSV = 1, /**< `frame,time,NAME_x,NAME_y,NAME_z,...`, calibration world frame, empty cells when
                               missing; `time` (1.6) in seconds from the take's first frame, from the frames'
                               timestamps (a live take's real set times). Readers accept CSVs without it. */
  OCTOCAP_MOTION_BVH = 2, /**< The bone animation: one joint per bone (Mixamo-style names), median bone lengths,
                               rig frame (Y up), centimetres. Frames come from octocap_motion_writer_add().
                               @since 0.3 */
  OCTOCAP_MOTION_CSV_PEOPLE = 3 /**< Several people: `frame,time,person,NAME_x,NAME_y,NAME_z,...` (`time`
                                     since 1.6), one row per
                                     octocap_motion_writer_add() of a person present (frame = the frame's index,
                                     person = its id), calibration world frame; empty frames add no row.
                                     @since 1.3 */
};

/**
 * Creates a writer. The file is written on octocap_motion_writer_close() (TRC needs the frame count in its
 * header).
 *
 * Time: each frame added keeps its timestamp (octocap_frame_summary_t.timestamp_us). The CSV says when each frame
 * happened. TRC and BVH rows are 1 / rate apart, so when the frames are not (a live take's sets come as the cameras
 * and the host allow) they are resampled onto that grid: positions interpolated, bone rotations slerped, nothing
 * invented across a stretch of more than a quarter of a second without frames (missing there).
 * `rate_hz`: the rate of TRC and BVH rows, 0.001 to 100000 Hz; or 0 (1.6): the frames' own mean rate, from their
 * timestamps (what a live take should use unless a fixed rate is wanted). Frames whose timestamps do not increase
 * (added with octocap_motion_writer_add_keypoints() or octocap_motion_writer_add_empty_frame(), or from solves all
 * given one time) are taken to be 1 / rate apart, at 30 Hz when `rate_hz` is 0.
 * @param[in]  path    The file to write at close.
 * @param[in]  format  An ::octocap_motion_format_values.
 * @param[in]  layout  The keypoints' layout (not AUTO).
 * @param[in]  up_axis The world's up axis (::OCTOCAP_UP_Z turns a TRC upright; other values mean Y).
 * @param[in]  rate_hz As above.
 * @param[out] out     The new writer (NULL on failure); close it with octocap_motion_writer_close() or
 *                     octocap_motion_writer_discard().
 * @retval OCTOCAP_OK                     `*out` is a new writer.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` or `out` is NULL, an unknown format, AUTO or an unknown layout, or a
 *                                        rate out of range.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The writer could not be allocated.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_create(const char* path, octocap_motion_format_t format,
                                                          octocap_layout_t layout, octocap_up_axis_t up_axis,
                                                          double rate_hz, octocap_motion_writer_t** out);
/**
 * Appends the layout keypoints (and for BVH the bones) of person `person` of `frame`; a frame with no such person
 * adds an empty frame.
 * @param[in] writer A writer.
 * @param[in] frame  A frame of the writer's layout.
 * @param[in] person The person's index in the frame (0 .. person_count - 1); a ::OCTOCAP_MOTION_CSV_PEOPLE writer
 *                   is given each person present, one call each.
 * @retval OCTOCAP_OK                     The frame is added.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `writer` or `frame` is not a live handle.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT The frame's layout is not the writer's.
 * @retval OCTOCAP_ERROR_IO               The journal (octocap_motion_writer_set_journal()) cannot be written.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_add(octocap_motion_writer_t* writer, const octocap_frame_t* frame,
                                                       uint32_t person);
/**
 * Appends `count` 3D keypoints (layout order, as from octocap_frame_get_keypoints3d()).
 * @param[in] writer    A TRC or CSV writer.
 * @param[in] keypoints `count` points; those with valid = 0 are missing.
 * @param[in] count     The layout's keypoint count.
 * @retval OCTOCAP_OK                     The frame is added.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `writer` is not a live writer.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `keypoints` is NULL, or `count` is not the layout's keypoint count.
 * @retval OCTOCAP_ERROR_UNSUPPORTED      A BVH or ::OCTOCAP_MOTION_CSV_PEOPLE writer (add frames instead).
 * @retval OCTOCAP_ERROR_IO               The journal cannot be written.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.2
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_keypoints(octocap_motion_writer_t* writer,
                                                                 const octocap_joint_t* keypoints, uint32_t count);
/**
 * Appends an empty frame (nothing solved), with no time of its own: the take is then taken as evenly spaced.
 * A ::OCTOCAP_MOTION_CSV_PEOPLE writer adds no row.
 * @param[in] writer A writer.
 * @retval OCTOCAP_OK                   The frame is added.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `writer` is not a live writer.
 * @retval OCTOCAP_ERROR_IO             The journal cannot be written.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_empty_frame(octocap_motion_writer_t* writer);
/**
 * Appends an empty frame that happened at `timestamp_us` (the same clock as the frames added).
 * @param[in] writer       A writer.
 * @param[in] timestamp_us When the frame happened, microseconds.
 * @retval OCTOCAP_OK                   The frame is added.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `writer` is not a live writer.
 * @retval OCTOCAP_ERROR_IO             The journal cannot be written.
 * @since 1.6
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_add_empty_frame_at(octocap_motion_writer_t* writer,
                                                                      int64_t timestamp_us);
/**
 * Before the first frame: every frame added is also appended to `journal_path` as it comes, a CSV of the layout
 * keypoints with their times (the format of ::OCTOCAP_MOTION_CSV, or ::OCTOCAP_MOTION_CSV_PEOPLE for such a writer),
 * flushed each frame. A take whose process dies (killed, a power cut) keeps every frame but the one being added, in a
 * file octocap_motion_open() and the viewer read. The journal is deleted once octocap_motion_writer_close() wrote the
 * file, and by octocap_motion_writer_discard(): it exists only for a take that never ended. A BVH writer's journal
 * holds keypoints, not bones.
 * @param[in] writer       A writer no frame was added to yet.
 * @param[in] journal_path The journal's path.
 * @retval OCTOCAP_OK                     Frames are journalled from now on.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `writer` is not a live writer.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `journal_path` is NULL, or frames were added already.
 * @retval OCTOCAP_ERROR_IO               The journal cannot be made.
 * @since 1.7
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_set_journal(octocap_motion_writer_t* writer,
                                                               const char* journal_path);
/**
 * Writes the file and destroys the writer (also on failure). NULL is accepted.
 * @param[in] writer A writer, or NULL; it is gone after the call, whatever the result (but for INVALID_HANDLE).
 * @retval OCTOCAP_OK                   The file is written (or `writer` was NULL).
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `writer` is not a live writer (nothing is destroyed).
 * @retval OCTOCAP_ERROR_IO             The file cannot be opened or written.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY  An allocation failed while resampling or writing.
 * @since 0.1
 */
OCTOCAP_API octocap_result_t octocap_motion_writer_close(octocap_motion_writer_t* writer);
/**
 * Destroys the writer without writing anything (a take that failed leaves no partial file). NULL is accepted.
 * @param[in] writer A writer, or NULL.
 * @since 1.0
 */
OCTOCAP_API void octocap_motion_writer_discard(octocap_motion_writer_t* writer);

/** A motion file opened for playback as the paper's skeleton: what drives an avatar from a file. @since 0.3 */
typedef struct octocap_motion_t octocap_motion_t;

/**
 * Opens a motion file: a TRC or CSV of keypoints (octocap's, Pose2Sim's; the layout is found from the marker
 * names, a Z-up CSV is turned upright) or a BVH (CMU, Mixamo-style or octocap's own joint names; units found
 * from the skeleton's size).
 *
 * (1.6) A several-people CSV (OCTOCAP_MOTION_CSV_PEOPLE) gives frames with each person present, under the ids the
 * file gives them; every other file holds one person, id 1. Frames are 1 / rate apart: a file that says its frames
 * came unevenly (a live take's CSV `time` column) is resampled at its mean rate, and the rate is that of its
 * times; frame i's timestamp_us is i / rate.
 * @param[in]  path A .trc, .csv or .bvh file.
 * @param[out] out  The new motion (NULL on failure); destroy it with octocap_motion_destroy().
 * @retval OCTOCAP_OK                     `*out` is a new motion.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `path` or `out` is NULL, or an unknown extension.
 * @retval OCTOCAP_ERROR_IO               The file cannot be opened.
 * @retval OCTOCAP_ERROR_PARSE            Malformed, no frames, or no humanoid skeleton found (marker or joint names
 *                                        that match no layout).
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The motion could not be allocated.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_motion_open(const char* path, octocap_motion_t** out);
/**
 * Destroys a motion; NULL is accepted.
 * @param[in] motion A motion, or NULL.
 * @since 0.3
 */
OCTOCAP_API void octocap_motion_destroy(octocap_motion_t* motion);
/**
 * Frame count and frame rate (Hz) of the motion.
 * @param[in]  motion      A motion.
 * @param[out] frame_count The frame count, or NULL.
 * @param[out] rate_hz     The frame rate, Hz, or NULL.
 * @retval OCTOCAP_OK                   The values asked for are set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `motion` is not a live motion.
 * @since 0.3
 */
OCTOCAP_API octocap_result_t octocap_motion_info(const octocap_motion_t* motion, uint32_t* frame_count, double* rate_hz);
/**
 * Frame `index` as a frame handle (one person, id 1, when the file has joints there; joints in the rig frame; bone
 * poses solved once at open, exactly as a session solves them).
 * @param[in]  motion A motion.
 * @param[in]  index  0 .. frame count - 1.
 * @param[out] out    The new frame handle (NULL on failure).
 * @retval OCTOCAP_OK                     `*out` is a new frame.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, or `index` is out of range.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `motion` is not a live motion.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    The frame could not be allocated.
 * @since 1.0
 */
OCTOCAP_API octocap_result_t octocap_motion_get_frame(const octocap_motion_t* motion, uint32_t index,
                                                      octocap_frame_t** out);

/** @} */
/* ------------------------------------------------------------------------------------------------------ */
/**
 * @name Deprecated: the per-source queries of 0.x
 *
 * Kept so that programs built against 0.x keep working; new code reads frames (octocap_frame_*). Each reads the
 * source's current frame (person 0) as the frame queries do; a frame with nobody in it gives invalid joints.
 * Superseded by the frames of 1.0; since 1.9 a call warns at compile time (OCTOCAP_DEPRECATED()).
 */
/** @{ */

/* Deprecated in words only: the struct has no deprecation attribute, and clang's -Wdocumentation reports a
 * documented deprecation without one in every program that includes this header. */
/** Frame-level summary of the last solve, as the deprecated queries below give it. Superseded in 1.0 by
 *  ::octocap_frame_summary_t and ::octocap_person_t of a frame.
 *  @since 0.1 */
typedef struct octocap_frame_info_t {
  int64_t frame_index;          /**< 0 for the first solved frame of the session. */
  int64_t timestamp_us;         /**< Frame time given to the solve. */
  uint32_t keypoints_solved;    /**< Layout keypoints with valid = 1. */
  uint32_t keypoints_total;     /**< Layout keypoints. */
  float mean_reprojection_error_px; /**< Mean over solved keypoints. */
  uint32_t views_with_person;   /**< Views in which a person was selected. */
  float solve_ms;               /**< Wall time of the 3D solve of this frame. */
} octocap_frame_info_t;

/**
 * Summary of the last frame.
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_summary() and octocap_frame_get_person().
 * @param[in]  session A session.
 * @param[out] out     The summary.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_frame_info(const octocap_session_t* session,
                                                            octocap_frame_info_t* out);

/**
 * The 3D layout keypoints of the last frame (capacity >= layout keypoint count; NULL out to query count).
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_keypoints3d().
 * @param[in]  session  A session.
 * @param[out] out      `capacity` points, or NULL to learn the count.
 * @param[in]  capacity Points `out` holds.
 * @param[out] count    The keypoint count, set also when the buffer is short.
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below `*count`.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_keypoints3d(const octocap_session_t* session, octocap_joint_t* out,
                                                             uint32_t capacity, uint32_t* count);

/**
 * The ::OCTOCAP_JOINT_COUNT skeleton joints of the last frame (NULL out to query the count).
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_joints().
 * @param[in]  session  A session.
 * @param[out] out      `capacity` joints, or NULL to learn the count.
 * @param[in]  capacity Joints `out` holds (at least 15, as for octocap_frame_get_joints()).
 * @param[out] count    The joints given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 15.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_joints(const octocap_session_t* session, octocap_joint_t* out,
                                                        uint32_t capacity, uint32_t* count);

/**
 * Index of the person selected in each view for the last frame (-1 = none).
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_person_views().
 * @param[in]  session  A session.
 * @param[out] out      `capacity` indices, in calibration order; or NULL to learn the count.
 * @param[in]  capacity Indices `out` holds.
 * @param[out] count    The view count, set also when the buffer is short.
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below `*count`.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_selected_people(const octocap_session_t* session, int32_t* out,
                                                                 uint32_t capacity, uint32_t* count);

/**
 * The ::OCTOCAP_BONE_COUNT bone poses of the last frame, converted to `frame` (NULL out to query the count).
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_bones().
 * @param[in]  session  A session.
 * @param[in]  frame    The coordinate frame to give rotations and positions in.
 * @param[out] out      `capacity` poses, or NULL to learn the count.
 * @param[in]  capacity Poses `out` holds (at least 13, as for octocap_frame_get_bones()).
 * @param[out] count    The bones given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL, or `frame` is no ::octocap_coord_frame_values.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 13.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_bones(const octocap_session_t* session, octocap_coord_frame_t frame,
                                                       octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count);

/**
 * Local rotation of one bone (convenience over octocap_session_get_bones).
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_frame_get_bones() (its local_rotation).
 * @param[in]  session A session.
 * @param[in]  bone    An ::octocap_bone_id_t.
 * @param[in]  frame   The coordinate frame of the rotation.
 * @param[out] out     The bone's rotation relative to its parent.
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_NO_RESULT        Before the first solve.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL, `bone` is out of range, or `frame` is no
 *                                        ::octocap_coord_frame_values.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_get_bone_rotation(const octocap_session_t* session, uint32_t bone,
                                                               octocap_coord_frame_t frame, octocap_quat_t* out);

/**
 * Counter that changes whenever the skeleton definition changes (layout, bone table). A consumer caches the
 * definition and re-reads it when this changes.
 * @deprecated Since 1.0: octocap_frame_summary_t.definition_counter of each frame.
 * @param[in]  session A session.
 * @param[out] out     The counter (never 0).
 * @retval OCTOCAP_OK                     `*out` is set.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `session` is not a live session.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_session_definition_counter(const octocap_session_t* session, uint32_t* out);

/**
 * Takes the next pose as the subscriber's current frame (as in 0.x).
 * @deprecated Since 1.0: octocap_subscriber_take_frame(), which returns the frame and a status for a timeout.
 * @param[in] sub        A subscriber.
 * @param[in] timeout_ms Longest wait, milliseconds; 0: do not wait.
 * @retval OCTOCAP_OK                   A pose is the current frame.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_NO_RESULT      None arrived in time (as in 0.x).
 * @since 0.2
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_subscriber_take(octocap_subscriber_t* sub, int32_t timeout_ms);
/**
 * As octocap_session_get_frame_info(), for the current received frame (solve_ms is 0).
 * @deprecated Since 1.0: octocap_subscriber_take_frame(), then octocap_frame_get_summary().
 * @param[in]  sub A subscriber.
 * @param[out] out The summary.
 * @retval OCTOCAP_OK                     `*out` is filled.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_NO_RESULT        No pose received yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `out` is NULL.
 * @since 0.2
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_subscriber_get_frame_info(const octocap_subscriber_t* sub,
                                                               octocap_frame_info_t* out);
/**
 * As octocap_session_get_keypoints3d(), for the current received frame.
 * @deprecated Since 1.0: octocap_subscriber_take_frame(), then octocap_frame_get_keypoints3d().
 * @param[in]  sub      A subscriber.
 * @param[out] out      `capacity` points, or NULL to learn the count.
 * @param[in]  capacity Points `out` holds.
 * @param[out] count    The keypoint count, set also when the buffer is short.
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_NO_RESULT        No pose received yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below `*count`.
 * @since 0.2
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_subscriber_get_keypoints3d(const octocap_subscriber_t* sub, octocap_joint_t* out,
                                                                uint32_t capacity, uint32_t* count);
/**
 * As octocap_session_get_joints(), for the current received frame.
 * @deprecated Since 1.0: octocap_subscriber_take_frame(), then octocap_frame_get_joints().
 * @param[in]  sub      A subscriber.
 * @param[out] out      `capacity` joints, or NULL to learn the count.
 * @param[in]  capacity Joints `out` holds (at least 15).
 * @param[out] count    The joints given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_NO_RESULT        No pose received yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 15.
 * @since 0.2
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_subscriber_get_joints(const octocap_subscriber_t* sub, octocap_joint_t* out,
                                                           uint32_t capacity, uint32_t* count);
/**
 * As octocap_session_get_bones(), for the current received frame.
 * @deprecated Since 1.0: octocap_subscriber_take_frame(), then octocap_frame_get_bones().
 * @param[in]  sub      A subscriber.
 * @param[in]  frame    The coordinate frame to give rotations and positions in.
 * @param[out] out      `capacity` poses, or NULL to learn the count.
 * @param[in]  capacity Poses `out` holds (at least 13).
 * @param[out] count    The bones given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `sub` is not a live subscriber.
 * @retval OCTOCAP_ERROR_NO_RESULT        No pose received yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL, or `frame` is no ::octocap_coord_frame_values.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 13.
 * @since 0.2
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_subscriber_get_bones(const octocap_subscriber_t* sub, octocap_coord_frame_t frame,
                                                          octocap_bone_pose_t* out, uint32_t capacity,
                                                          uint32_t* count);

/**
 * Appends the last frame's layout keypoints of `session`.
 * @deprecated Since 1.0: octocap_session_get_frame(), then octocap_motion_writer_add().
 * @param[in] writer  A writer.
 * @param[in] session A session that solved a frame.
 * @retval OCTOCAP_OK                     The frame is added.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `writer` or `session` is not a live handle.
 * @retval OCTOCAP_ERROR_NO_RESULT        The session has not solved a frame yet.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT The session's layout is not the writer's.
 * @retval OCTOCAP_ERROR_IO               The journal cannot be written.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.1
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_motion_writer_add_frame(octocap_motion_writer_t* writer,
                                                             const octocap_session_t* session);
/**
 * The 15 skeleton joints of `frame` (::octocap_joint_id_values order), rig frame (Y up, metres); valid = 0 where
 * the file has none.
 * @deprecated Since 1.0: octocap_motion_get_frame(), then octocap_frame_get_joints().
 * @param[in]  motion   A motion.
 * @param[in]  frame    0 .. frame count - 1.
 * @param[out] out      `capacity` joints, or NULL to learn the count.
 * @param[in]  capacity Joints `out` holds (at least 15).
 * @param[out] count    The joints given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `motion` is not a live motion.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL, or `frame` is out of range.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 15.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.3
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_motion_joints(const octocap_motion_t* motion, uint32_t frame,
                                                   octocap_joint_t* out, uint32_t capacity, uint32_t* count);
/**
 * The bone poses of `frame`, solved from its joints exactly as a session does (anti-spin, relative to the
 * T-pose), in the requested coordinate frame.
 * @deprecated Since 1.0: octocap_motion_get_frame(), then octocap_frame_get_bones().
 * @param[in]  motion      A motion.
 * @param[in]  frame       0 .. frame count - 1.
 * @param[in]  coord_frame The coordinate frame to give rotations and positions in.
 * @param[out] out         `capacity` poses, or NULL to learn the count.
 * @param[in]  capacity    Poses `out` holds (at least 13).
 * @param[out] count       The bones given (or needed).
 * @retval OCTOCAP_OK                     `*count` is set, and `out` filled when given.
 * @retval OCTOCAP_ERROR_INVALID_HANDLE   `motion` is not a live motion.
 * @retval OCTOCAP_ERROR_INVALID_ARGUMENT `count` is NULL, `frame` is out of range, or `coord_frame` is no
 *                                        ::octocap_coord_frame_values.
 * @retval OCTOCAP_ERROR_BUFFER_TOO_SMALL `capacity` is below 13.
 * @retval OCTOCAP_ERROR_OUT_OF_MEMORY    An allocation failed.
 * @since 0.3
 */
OCTOCAP_DEPRECATED("a 0.x query: read a frame (octocap_frame_*) instead")
OCTOCAP_API octocap_result_t octocap_motion_bones(const octocap_motion_t* motion, uint32_t frame,
                                                  octocap_coord_frame_t coord_frame, octocap_bone_pose_t* out,
                                                  uint32_t capacity, uint32_t* count);

/** @} */

#ifdef __cplusplus
}
#endif

#endif /* OCTOCAP_OCTOCAP_H */
