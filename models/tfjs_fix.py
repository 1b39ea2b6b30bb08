"""Repairs TF.js graphs so that tf2onnx 1.17 can read them with TensorFlow 2.21.

Why: the MoveNet graphs were exported by an older TF.js converter that left out attributes newer TensorFlow
requires when tf2onnx re-imports single nodes to infer shapes (`_FusedConv2D` needs `TArgs`, `TopKV2` needs
`index_type`). The fix only adds the attribute values the older TensorFlow implied; weights are untouched.
Usage: python tfjs_fix.py IN_DIR/model.json OUT_DIR/model.json  (the .bin shards are copied alongside).
"""
import json
import os
import shutil
import sys


def fix_node(node):
    attr = node.setdefault("attr", {})
    if node["op"] in ("_FusedConv2D", "FusedDepthwiseConv2dNative", "_FusedMatMul") and "TArgs" not in attr:
        count = int(attr.get("num_args", {}).get("i", "1"))
        dtype = attr.get("T", {}).get("type", "DT_FLOAT")
        attr["TArgs"] = {"list": {"type": [dtype] * count}}
        return True
    if node["op"] == "TopKV2" and "index_type" not in attr:
        attr["index_type"] = {"type": "DT_INT32"}
        return True
    return False


def main(src, dst):
    with open(src, encoding="utf-8") as f:
        model = json.load(f)
    fixed = sum(fix_node(n) for n in model["modelTopology"]["node"])
    for fn in model["modelTopology"].get("library", {}).get("function", []):
        fixed += sum(fix_node(n) for n in fn.get("nodeDef", []))
    os.makedirs(os.path.dirname(os.path.abspath(dst)), exist_ok=True)
    with open(dst, "w", encoding="utf-8") as f:
        json.dump(model, f)
    src_dir = os.path.dirname(os.path.abspath(src))
    for group in model["weightsManifest"]:
        for shard in group["paths"]:
            shutil.copyfile(os.path.join(src_dir, shard), os.path.join(os.path.dirname(os.path.abspath(dst)), shard))
    print(f"{os.path.basename(src)}: {fixed} nodes repaired")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
