"""BlazePose GHUM landmark model (MediaPipe, Apache-2.0), from the .tflite in npm @mediapipe/pose to the ONNX octocap runs.

Why a second step after tf2onnx: the model answers five things (landmarks, a person flag, a segmentation mask, heatmaps,
world landmarks); octocap reads the first two, and the mask's decoder alone costs a good part of the inference. The
graph is cut to those two outputs (onnx.utils.extract_model) and then checked against the original .tflite (TF Lite's
interpreter from tensorflow-cpu) on real photos: a conversion can load and run and still be wrong.

Usage: python blazepose.py CONVERTED.onnx ORIGINAL.tflite OUT.onnx PHOTO...
Exit status 1 when a landmark differs by more than the tolerance.
"""
import sys

import numpy as np
import onnx
import onnx.utils
import onnxruntime as ort
import tensorflow as tf

SIDE = 256
TOLERANCE_PX = 0.05  # landmark coordinates, input pixels; float reordering gives ~1e-3
TOLERANCE_SCORE = 1e-2  # visibility / presence logits and the person flag


def square_crop(photo):
    """The photo's centred square, resized to the input side: a person fills it as a crop around them would."""
    image = tf.io.decode_image(tf.io.read_file(photo), channels=3, expand_animations=False)
    h, w = image.shape[0], image.shape[1]
    side = min(h, w)
    image = tf.image.crop_to_bounding_box(image, (h - side) // 2, (w - side) // 2, side, side)
    image = tf.image.resize(tf.cast(image, tf.float32), (SIDE, SIDE))
    return (image.numpy() / 255.0).astype(np.float32)[None]


def main(converted, original, out, *photos):
    model = onnx.load(converted)
    names = [o.name for o in model.graph.output]
    shapes = {o.name: [d.dim_value for d in o.type.tensor_type.shape.dim] for o in model.graph.output}
    landmarks = next(n for n in names if shapes[n][-1] == 195)
    flag = next(n for n in names if shapes[n][-1] == 1 and len(shapes[n]) == 2)
    onnx.utils.extract_model(converted, out, [model.graph.input[0].name], [landmarks, flag])

    session = ort.InferenceSession(out, providers=["CPUExecutionProvider"])
    interpreter = tf.lite.Interpreter(model_path=original)
    interpreter.allocate_tensors()
    details = {tuple(d["shape"]): d["index"] for d in interpreter.get_output_details()}
    worst_px = worst_score = 0.0
    for photo in photos:
        pixels = square_crop(photo)
        got_lm, got_flag = session.run(None, {session.get_inputs()[0].name: pixels})
        interpreter.set_tensor(interpreter.get_input_details()[0]["index"], pixels)
        interpreter.invoke()
        want_lm = interpreter.get_tensor(details[(1, 195)]).reshape(39, 5)
        want_flag = interpreter.get_tensor(details[(1, 1)])
        got_lm = got_lm.reshape(39, 5)
        worst_px = max(worst_px, float(np.max(np.abs(got_lm[:, :2] - want_lm[:, :2]))))
        worst_score = max(worst_score, float(np.max(np.abs(got_lm[:, 3:] - want_lm[:, 3:]))),
                          float(np.max(np.abs(got_flag - want_flag))))
        print(f"{photo}: person flag {float(want_flag.ravel()[0]):.3f}, nose at ({want_lm[0, 0]:.1f}, {want_lm[0, 1]:.1f})")
    print(f"{out}: max |ONNX - TF Lite| = {worst_px:.2e} px (tolerance {TOLERANCE_PX}), scores {worst_score:.2e} "
          f"(tolerance {TOLERANCE_SCORE}), {len(photos)} photos")
    return 0 if worst_px <= TOLERANCE_PX and worst_score <= TOLERANCE_SCORE else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
