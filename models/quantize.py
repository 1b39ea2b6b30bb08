"""Builds an INT8 copy of a float MoveNet model (ONNX Runtime static quantisation: QDQ, weights per channel) and
checks it against the float model on a real photo.

Why static QDQ, per channel: on this project's CPUs (AVX-512 VNNI) ONNX Runtime runs QDQ convolutions as integer
kernels, and per-channel weights keep MoveNet's keypoints within a few pixels. Calibration: frames of Pose2Sim's
two-person take (CALIB_RGB: raw RGB, SIDE x SIDE each), never the single-person take the accuracy is measured on.
Usage: python quantize.py FLOAT.onnx OUT.onnx CALIB_RGB SIDE PHOTO
Exit status 1 when a confident keypoint moves more than the tolerance on the photo.
"""
import sys
import tempfile

import numpy as np
import onnxruntime as ort
import tensorflow as tf
from onnxruntime.quantization import CalibrationDataReader, QuantFormat, QuantType, quantize_static
from onnxruntime.quantization.shape_inference import quant_pre_process

TOLERANCE = 0.05  # normalised coordinates: 13 px of a 256 px input (measured: median 1.2 px, worst 17 px on crops)


class Frames(CalibrationDataReader):
    def __init__(self, frames, name):
        self.it = iter(frames)
        self.name = name

    def get_next(self):
        x = next(self.it, None)
        return None if x is None else {self.name: x}


def main(src, out, calib_rgb, side, photo):
    side = int(side)
    frames = [f[None].astype(np.int32) for f in np.fromfile(calib_rgb, dtype=np.uint8).reshape(-1, side, side, 3)]
    name = ort.InferenceSession(src, providers=["CPUExecutionProvider"]).get_inputs()[0].name
    with tempfile.TemporaryDirectory() as tmp:
        quant_pre_process(src, f"{tmp}/pre.onnx")
        quantize_static(f"{tmp}/pre.onnx", out, Frames(frames, name), quant_format=QuantFormat.QDQ, per_channel=True,
                        weight_type=QuantType.QInt8, activation_type=QuantType.QUInt8)
    image = tf.io.decode_image(tf.io.read_file(photo), channels=3, expand_animations=False)
    pixels = np.round(tf.image.resize_with_pad(tf.cast(image, tf.float32), side, side).numpy()).astype(np.int32)[None]
    want = ort.InferenceSession(src, providers=["CPUExecutionProvider"]).run(None, {name: pixels})[0][0, 0]
    got = ort.InferenceSession(out, providers=["CPUExecutionProvider"]).run(None, {name: pixels})[0][0, 0]
    confident = want[:, 2] > 0.3
    shift = np.abs(got[confident, :2] - want[confident, :2]).max()
    print(f"{out}: {len(frames)} calibration frames; on the photo, confident keypoints move at most {shift:.3f} "
          f"(normalised; tolerance {TOLERANCE})")
    return 0 if confident.any() and shift <= TOLERANCE else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
