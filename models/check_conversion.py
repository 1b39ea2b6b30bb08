"""Checks a converted ONNX model against the original TF.js graph on the same real photo.

Why: a conversion can load and run and still be wrong (a mis-read attribute shifts every keypoint). The photo is
letterboxed into the model's input exactly as octocap does, both frameworks run it, and the outputs must agree.
Usage: python check_conversion.py MODEL.onnx TFJS_MODEL.json PHOTO H W RUN_TFJS_JS
Exit status 1 when the largest difference exceeds the tolerance.
"""
import subprocess
import sys
import tempfile

import numpy as np
import onnxruntime as ort
import tensorflow as tf

TOLERANCE = 2e-3  # normalised coordinates and scores; float32 reordering gives ~1e-5


def letterboxed(photo, h, w):
    image = tf.io.decode_image(tf.io.read_file(photo), channels=3, expand_animations=False)
    image = tf.image.resize_with_pad(tf.cast(image, tf.float32), h, w)
    return np.round(image.numpy()).astype(np.int32)[None]


def main(onnx_path, tfjs_json, photo, h, w, runner):
    h, w = int(h), int(w)
    pixels = letterboxed(photo, h, w)
    session = ort.InferenceSession(onnx_path, providers=["CPUExecutionProvider"])
    got = session.run(None, {session.get_inputs()[0].name: pixels})[0].astype(np.float32).ravel()
    with tempfile.TemporaryDirectory() as tmp:
        pixels.tofile(f"{tmp}/in.i32")
        subprocess.run(["node", runner, tfjs_json, f"{tmp}/in.i32", str(h), str(w), f"{tmp}/out.f32"], check=True)
        want = np.fromfile(f"{tmp}/out.f32", dtype=np.float32)
    if got.shape != want.shape:
        print(f"{onnx_path}: shape {got.shape} vs TF.js {want.shape}")
        return 1
    diff = float(np.max(np.abs(got - want)))
    print(f"{onnx_path}: max |ONNX - TF.js| = {diff:.2e} over {got.size} outputs (tolerance {TOLERANCE})")
    return 0 if diff <= TOLERANCE else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
