#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes tests/data/dnn/yolov8-known.onnx: a tiny ONNX detection network whose output is known exactly.

The graph is GlobalAveragePool -> Conv (1x1, all weights 0, bias B) -> Reshape [1, 6, 8]: whatever the image, the
output is B laid out as the YOLOv8 head's 1 x (4 + C) x N tensor (C = 2 classes, N = 8 anchors; row a holds
attribute a of every anchor: cx, cy, w, h in network-input pixels, then the two class scores). The input is
images 1x3x640x640; the global pooling makes the network run at any input size, as OpenCV's probe needs.

The protobuf is encoded by hand below (field numbers from onnx/onnx.proto), so no onnx or protobuf package is
needed: Python's standard library only. Deterministic: running it again writes the same bytes.
"""
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "dnn", "yolov8-known.onnx")

# The anchors: (cx, cy, w, h, class 0 score, class 1 score), in 640x640 input pixels. Every value is exact in
# binary floating point except the scores, which the tests compare with a tolerance.
ANCHORS = [
    (320, 320, 128, 64, 0.9, 0.1),   # class 0, 0.9
    (330, 320, 128, 64, 0.8, 0.0),   # class 0, 0.8, IoU 0.855 with anchor 0: suppressed by NMS
    (100, 220, 40, 80, 0.2, 0.75),   # class 1, 0.75
    (500, 500, 50, 50, 0.3, 0.4),    # best 0.4: below the 0.5 threshold
    (0, 0, 0, 0, 0.0, 0.0),
    (0, 0, 0, 0, 0.0, 0.0),
    (0, 0, 0, 0, 0.0, 0.0),
    (0, 0, 0, 0, 0.0, 0.0),
]
ATTRIBUTES = 6
N = len(ANCHORS)

# Wire types
VARINT, BYTES, FIXED32 = 0, 2, 5
FLOAT, INT64 = 1, 7  # TensorProto.DataType


def varint(n):
    out = bytearray()
    n &= (1 << 64) - 1  # negative int64 as two's complement, as protobuf does
    while True:
        b = n & 0x7F
        n >>= 7
        if n:
            out.append(b | 0x80)
        else:
            out.append(b)
            return bytes(out)


def key(field, wire):
    return varint(field << 3 | wire)


def f_varint(field, n):
    return key(field, VARINT) + varint(n)


def f_bytes(field, data):
    if isinstance(data, str):
        data = data.encode()
    return key(field, BYTES) + varint(len(data)) + data


def tensor(name, dims, data_type, values):
    """TensorProto: dims = 1, data_type = 2, name = 8, raw_data = 9 (little-endian)."""
    fmt = "<%d%s" % (len(values), "f" if data_type == FLOAT else "q")
    return (b"".join(f_varint(1, d) for d in dims) + f_varint(2, data_type) + f_bytes(8, name) +
            f_bytes(9, struct.pack(fmt, *values)))


def attr_ints(name, values):
    """AttributeProto: name = 1, ints = 8, type = 20 (INTS = 7)."""
    return f_bytes(1, name) + b"".join(f_varint(8, v) for v in values) + f_varint(20, 7)


def node(op, inputs, outputs, name, attributes=()):
    """NodeProto: input = 1, output = 2, name = 3, op_type = 4, attribute = 5."""
    return (b"".join(f_bytes(1, i) for i in inputs) + b"".join(f_bytes(2, o) for o in outputs) + f_bytes(3, name) +
            f_bytes(4, op) + b"".join(f_bytes(5, a) for a in attributes))


def value_info(name, dims):
    """ValueInfoProto: name = 1, type = 2; TypeProto.tensor_type = 1; Tensor: elem_type = 1, shape = 2;
    TensorShapeProto.dim = 1; Dimension.dim_value = 1."""
    shape = b"".join(f_bytes(1, f_varint(1, d)) for d in dims)
    return f_bytes(1, name) + f_bytes(2, f_bytes(1, f_varint(1, FLOAT) + f_bytes(2, shape)))


def model():
    channels = ATTRIBUTES * N
    # Conv output channel a * N + i becomes element (a, i) of the 1 x 6 x 8 reshape.
    bias = [float(ANCHORS[i][a]) for a in range(ATTRIBUTES) for i in range(N)]
    graph = b"".join([
        f_bytes(1, node("GlobalAveragePool", ["images"], ["pooled"], "pool")),
        f_bytes(1, node("Conv", ["pooled", "conv.weight", "conv.bias"], ["conv"], "head",
                        [attr_ints("kernel_shape", [1, 1])])),
        f_bytes(1, node("Reshape", ["conv", "shape"], ["output0"], "to_yolov8")),
        f_bytes(2, "yolov8-known"),
        f_bytes(5, tensor("conv.weight", [channels, 3, 1, 1], FLOAT, [0.0] * (channels * 3))),
        f_bytes(5, tensor("conv.bias", [channels], FLOAT, bias)),
        f_bytes(5, tensor("shape", [3], INT64, [1, ATTRIBUTES, N])),
        f_bytes(11, value_info("images", [1, 3, 640, 640])),
        f_bytes(12, value_info("output0", [1, ATTRIBUTES, N])),
    ])
    opset = f_bytes(1, "") + f_varint(2, 13)  # OperatorSetIdProto: domain = 1, version = 2
    # ModelProto: ir_version = 1, producer_name = 2, graph = 7, opset_import = 8
    return f_varint(1, 7) + f_bytes(2, "benchscope scripts/make-onnx-fixture.py") + f_bytes(7, graph) + f_bytes(8, opset)


def main():
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "wb") as f:
        f.write(model())
    print(os.path.normpath(OUT))


if __name__ == "__main__":
    main()
