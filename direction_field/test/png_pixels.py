"""The RGB pixels of the program's --png pictures (8-bit RGB, filter type 0
on every row, as png_snapshot.h writes them), for the command-line test's
checks: `width, height, pixels = read_png(path)`, pixels a list of (r, g, b)."""
import struct
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + " is not a PNG file"
    width, height = struct.unpack(">II", data[16:24])
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"IDAT":
            idat += data[pos + 8:pos + 8 + length]
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = 3 * width + 1
    assert len(raw) == height * stride, path + ": unexpected image data size"
    pixels = []
    for r in range(height):
        row = raw[r * stride + 1:(r + 1) * stride]
        pixels.extend(tuple(row[i:i + 3]) for i in range(0, len(row), 3))
    return width, height, pixels
