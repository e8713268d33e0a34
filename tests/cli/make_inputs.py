"""Crafted inputs for tests/cli/test_doors.sh, with the standard library alone (PNG spec
section 5, APNG 1.0, OpenEXR file layout):
    make_inputs.py apng PATH W H FRAMES        an RGBA APNG of FRAMES whole frames
    make_inputs.py bigchunk IN OUT MIB          IN with an ancillary chunk of MIB MiB before IEND
    make_inputs.py exrclaim IN OUT W H          IN (a one-block EXR) with its data window set to W x H
    make_inputs.py nandepth PATH W H            a W x H depth EXR (channel Z, uncompressed) of 0.5 with a NaN
"""
import struct
import sys
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def apng(path, w, h, frames):
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
    out = [b"\x89PNG\r\n\x1a\n", chunk(b"IHDR", ihdr), chunk(b"acTL", struct.pack(">II", frames, 0))]
    seq = 0
    for f in range(frames):
        rows = b"".join(b"\0" + b"".join(bytes(((x * 7 + y * 3 + f * 40) % 256, (x * 5) % 256, (y * 9) % 256, 255))
                                          for x in range(w)) for y in range(h))
        data = zlib.compress(rows)
        out.append(chunk(b"fcTL", struct.pack(">IIIIIHHBB", seq, w, h, 0, 0, 1, 25, 0, 0)))
        seq += 1
        if f == 0:
            out.append(chunk(b"IDAT", data))
        else:
            out.append(chunk(b"fdAT", struct.pack(">I", seq) + data))
            seq += 1
    out.append(chunk(b"IEND", b""))
    open(path, "wb").write(b"".join(out))


def bigchunk(src, dst, mib):
    d = open(src, "rb").read()
    assert d[-12:-8] == b"\0\0\0\0" and d[-8:-4] == b"IEND"
    open(dst, "wb").write(d[:-12] + chunk(b"zzZz", bytes(mib << 20)) + d[-12:])


def exrclaim(src, dst, w, h):
    """A file that claims w x h pixels with a whole line offset table (so OpenEXR opens it):
    every 16-line ZIP block is a copy of src's one small block."""
    d = bytes(open(src, "rb").read())
    at = d.index(b"dataWindow\0box2i\0") + len(b"dataWindow\0box2i\0") + 4
    header = d[:at] + struct.pack("<iiii", 0, 0, w - 1, h - 1) + d[at + 16:]
    table_at, block = None, None
    # src has one block: its table entry is the 8 bytes before the block, which holds
    # int32 y, int32 size, then size bytes, up to the end of the file.
    for start in range(at + 16, len(d) - 16):
        off = struct.unpack("<Q", d[start:start + 8])[0]
        if off == start + 8 and struct.unpack("<i", d[off + 4:off + 8])[0] == len(d) - off - 8:
            table_at, block = start, d[off + 8:]
            break
    assert block is not None, "src is not a one-block EXR"
    header = header[:table_at]
    blocks = (h + 15) // 16
    first = table_at + 8 * blocks
    size = 8 + len(block)
    table = b"".join(struct.pack("<Q", first + k * size) for k in range(blocks))
    body = b"".join(struct.pack("<ii", 16 * k, len(block)) + block for k in range(blocks))
    open(dst, "wb").write(header + table + body)


def attr(name, kind, data):
    return name + b"\0" + kind + b"\0" + struct.pack("<i", len(data)) + data


def nandepth(path, w, h):
    """A scanline EXR without compression (one line per block): FLOAT channel Z, 0.5 except one NaN."""
    header = b"".join([
        struct.pack("<ii", 20000630, 2),
        attr(b"channels", b"chlist", b"Z\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1) + b"\0"),
        attr(b"compression", b"compression", b"\0"),
        attr(b"dataWindow", b"box2i", struct.pack("<iiii", 0, 0, w - 1, h - 1)),
        attr(b"displayWindow", b"box2i", struct.pack("<iiii", 0, 0, w - 1, h - 1)),
        attr(b"lineOrder", b"lineOrder", b"\0"),
        attr(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0)),
        attr(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0.0, 0.0)),
        attr(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)),
        b"\0"])
    first = len(header) + 8 * h
    size = 8 + 4 * w
    table = b"".join(struct.pack("<Q", first + y * size) for y in range(h))
    rows = []
    for y in range(h):
        values = [0.5] * w
        if y == h // 2:
            values[w // 2] = float("nan")
        rows.append(struct.pack("<ii", y, 4 * w) + struct.pack(f"<{w}f", *values))
    open(path, "wb").write(header + table + b"".join(rows))


if __name__ == "__main__":
    kind, args = sys.argv[1], sys.argv[2:]
    if kind == "apng":
        apng(args[0], int(args[1]), int(args[2]), int(args[3]))
    elif kind == "bigchunk":
        bigchunk(args[0], args[1], int(args[2]))
    elif kind == "exrclaim":
        exrclaim(args[0], args[1], int(args[2]), int(args[3]))
    elif kind == "nandepth":
        nandepth(args[0], int(args[1]), int(args[2]))
    else:
        sys.exit(f"unknown kind {kind}")
