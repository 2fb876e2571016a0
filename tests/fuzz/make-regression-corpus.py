#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus and the regression corpus of the loaders.

    tests/fuzz/make-regression-corpus.py OUT_DIR

OUT_DIR/seeds/{obj,image,md2,crowd_xml,editor_scene,sound}/       small valid files the fuzzers start from
OUT_DIR/regression/{obj,image,md2,crowd_xml,editor_scene,sound}/  every input that ever broke a loader (issue 14's
                                                            cases first), generated here rather than committed

A regression file's name says what the loaders must do with it: "ok-..." must
load, "err-..." must be refused with an InputError. The image files go to
both the image and the height-map entry points (a height map may refuse an
image that loads, e.g. a 16-bit one, so only "err-" binds it). OBJ inputs carry
their MTL text after a line "#@mtl" (see FuzzTargets.hpp). Findings of later
fuzzing runs are added to the list at the end of this file, or, when small,
copied to tests/fuzz/findings/{obj,image,md2}/, which the replay also reads. The
MD2 files are written here with struct (md2() below), not by stoa::encodeMd2, so
the loader is checked against a second writer of the format. The crowd_xml
files are whole world files without includes (tests/crowd/CrowdXmlTests.cpp
checks the same mistakes with their lines). The editor_scene files are scene
files (tests/editor/EditorSceneFileTests.cpp checks the same mistakes with
their lines); the example scene assets/scenes/example.json is a seed.
"""
import math
import os
import struct
import sys
import zlib

sys.dont_write_bytecode = True   # the sound part is a module beside this file; leave no cache in the tree
from corpus_sound import sound_regression, sound_seeds  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MTL = "\n#@mtl\n"


def png(width, height, colour_type=2, depth=8, rows=None, cut=None, chunks_after=b""):
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour_type]
    row_bytes = (width * channels * depth + 7) // 8
    if rows is None:
        rows = b"".join(b"\0" + bytes((x * 7 + y * 13) & 255 for x in range(row_bytes)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
    if colour_type == 3:
        data += chunk(b"PLTE", bytes(range(48)))
    data += chunk(b"IDAT", zlib.compress(rows)) + chunks_after + chunk(b"IEND", b"")
    return data[:cut] if cut else data


def bmp(width, height, bits=24, pixels=None, header_only=False):
    row = (width * bits + 31) // 32 * 4
    palette = b"".join(bytes((i, 255 - i, i // 2, 0)) for i in range(256)) if bits == 8 else b""
    offset = 54 + len(palette)
    if header_only:
        pixels, palette = b"", b""
    elif pixels is None:
        pixels = b"".join(bytes((x * 5 + y * 11) & 255 for x in range(row)) for y in range(abs(height)))
    file_size = offset + len(pixels)
    return (b"BM" + struct.pack("<IHHI", file_size, 0, 0, offset) +
            struct.pack("<IiiHHIIiiII", 40, width, height, 1, bits, 0, len(pixels), 2835, 2835, 0, 0) + palette + pixels)


def bmp_os2(width, height):
    """An OS/2 1.x BMP: a 12-byte info header with 16-bit sizes, 24 bits per pixel, varied pixels."""
    row = (width * 24 + 31) // 32 * 4
    pixels = b"".join(bytes((x * 29 + y * 53 + 7) & 255 for x in range(row)) for y in range(height))
    offset = 14 + 12
    return b"BM" + struct.pack("<IHHI", offset + len(pixels), 0, 0, offset) + struct.pack("<IHHHH", 12, width, height, 1, 24) + pixels


def tga(width, height, image_type=2, bits=24, pixels=None):
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, image_type, 0, 0, 0, 0, 0, width, height, bits, 0)
    if pixels is None:
        pixels = bytes((i * 3) & 255 for i in range(width * height * bits // 8))
    return header + pixels


def pnm(header, samples=b""):
    return header.encode() + samples


def jpeg_frame_offset(data):
    at = 2
    while at + 4 <= len(data):
        marker = data[at + 1]
        length = struct.unpack(">H", data[at + 2:at + 4])[0]
        if marker in (0xC0, 0xC1, 0xC2):
            return at
        at += 2 + length
    raise ValueError("no SOF")


def jpeg_resized(data, width, height):
    at = jpeg_frame_offset(data)
    return data[:at + 5] + struct.pack(">HH", height, width) + data[at + 9:]


def jpeg_size(data):
    at = jpeg_frame_offset(data)
    height, width = struct.unpack(">HH", data[at + 5:at + 9])
    return width, height


def jpeg_scan_repeats_component():
    """The seed rgb16.jpg with its scan's three components all renamed to component 1."""
    data = bytearray(open(os.path.join(HERE, "seeds", "rgb16.jpg"), "rb").read())
    at = data.index(b"\xff\xda")
    for i in range(3):
        data[at + 5 + 2 * i] = 1
    return bytes(data)


def obj_polygon(corners, star=False, normals=False, turns=1, digits=7):
    lines = []
    for i in range(corners):
        angle = 2 * math.pi * turns * i / corners
        radius = (1.0 if i % 2 == 0 else 0.5) if star else 1.0
        lines.append("v %.*f %.*f 0" % (digits, radius * math.cos(angle), digits, radius * math.sin(angle)))
    if normals:
        lines.append("vn 0 0 1")
    lines.append("f " + " ".join(("%d//1" % (i + 1)) if normals else str(i + 1) for i in range(corners)))
    return "\n".join(lines) + "\n"


TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"


def seeds():
    jpg = {name: open(os.path.join(HERE, "seeds", name), "rb").read() for name in ("rgb16.jpg", "grey8.jpg")}
    images = {
        "rgb.png": png(5, 4), "grey.png": png(4, 3, 0), "rgba.png": png(3, 3, 6), "palette.png": png(4, 2, 3),
        "grey16.png": png(2, 2, 0, 16), "grey-alpha.png": png(2, 3, 4),
        "rgb.bmp": bmp(5, 3), "topdown.bmp": bmp(3, -2), "rgba.bmp": bmp(2, 2, 32), "palette.bmp": bmp(4, 2, 8),
        "os2.bmp": bmp_os2(3, 2),
        "rgb.tga": tga(3, 2), "grey.tga": tga(4, 2, 3, 8), "rgba.tga": tga(2, 2, 2, 32),
        "rle.tga": tga(4, 1, 10, 24, bytes((0x83, 1, 2, 3))),
        "p5.pgm": pnm("P5\n3 2\n255\n", bytes(range(6))), "p6.ppm": pnm("P6 2 1 255\n", bytes(range(6))),
        "p2.pgm": pnm("P2\n# ascii\n3 2\n15\n0 5 10\n15 3 1\n"), "p3.ppm": pnm("P3 2 1 255\n255 0 0 0 255 0\n"),
        "p5-16.pgm": pnm("P5 2 1 65535\n", b"\x12\x34\xff\xff"),
    }
    images.update(jpg)
    objs = {
        "triangle.obj": TRIANGLE + "vn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1\n",
        "quad.obj": "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/2 3/1 4/2\n",
        "negative.obj": TRIANGLE + "f -3 -2 -1\n",
        "ell.obj": "v 2 0 0\nv 2 0 -1\nv 1 0 -1\nv 1 0 -2\nv 0 0 -2\nv 0 0 0\nvn 0 1 0\nf 1//1 2//1 3//1 4//1 5//1 6//1\n",
        "hexagon.obj": obj_polygon(6),
        "materials.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl red\nf 1 2 3\nusemtl old wood\nf 3 2 1\n" + MTL +
                         "newmtl red\nKa 0.1 0 0\nKd 1 0 0\nKs 0.5\nNs 20\nd 1\nillum 2\nnewmtl old wood\nKd 0.4 0.3 0.2\n",
        "groups.obj": "o thing\ng part\ns 1\n" + TRIANGLE + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/1\nl 1 2\np 3\n",
    }
    return objs, images


def regression():
    floor = open(os.path.join(ROOT, "assets", "acropolis", "floor_diffuse.jpg"), "rb").read()
    width, height = jpeg_size(floor)
    images = {
        # Hangs and memory blow-ups
        "err-jpg-sof0-20000x20000.jpg": jpeg_resized(floor, 20000, 20000),
        "err-bmp-54-byte-header-20000x20000.bmp": bmp(20000, 20000, header_only=True),
        "err-bmp-54-byte-header-16000x16000.bmp": bmp(16000, 16000, header_only=True),
        "err-tga-header-only-16000x16000.tga": tga(16000, 16000, pixels=b""),
        "err-tga-rle-16000x16000-one-packet.tga": tga(16000, 16000, 10, 24, b"\xff\1\2\3"),
        "err-png-ihdr-16000x16000-tiny-idat.png": png(16000, 16000, rows=b"\0" * 100),
        "err-png-ihdr-20000x20000.png": png(20000, 20000, rows=b"\0"),
        # Garbage accepted
        "err-jpg-size-patched-up.jpg": jpeg_resized(floor, width, height * 2),
        "err-jpg-width-patched-up.jpg": jpeg_resized(floor, width + 64, height),
        "err-jpg-truncated-half.jpg": floor[:len(floor) // 2],
        "err-jpg-truncated-no-eoi.jpg": floor[:-2],
        "err-pgm-negative-size.pgm": pnm("P5\n-4 4\n255\n", bytes(16)),
        "err-pgm-zero-size.pgm": pnm("P5\n0 0\n255\n"),
        "err-pgm-width-4294967297.pgm": pnm("P5\n4294967297 1\n255\n", bytes(1)),
        "err-pgm-maxval-0.pgm": pnm("P5\n2 2\n0\n", bytes(4)),
        "err-pgm-maxval-past-int.pgm": pnm("P5\n2 2\n99999999999999999999\n", bytes(4)),
        "err-pgm-width-past-int.pgm": pnm("P5\n99999999999999999999 2\n255\n", bytes(4)),
        "err-ppm-maxval-65536.ppm": pnm("P6 1 1 65536\n", bytes(6)),
        "err-pgm-truncated.pgm": pnm("P5 4 4 255\n", bytes(10)),
        "err-p2-truncated.pgm": pnm("P2 3 3 255\n1 2 3 4\n"),
        "err-p2-sample-past-maxval.pgm": pnm("P2 2 1 15\n3 16\n"),
        # Valid files refused
        "ok-bmp-os2-12-byte-header-varied.bmp": bmp_os2(7, 5),
        "ok-pgm-ascii-p2.pgm": pnm("P2\n# a comment\n4 2\n255\n0 64 128 255\n255 128 64 0\n"),
        "ok-ppm-ascii-p3.ppm": pnm("P3\n2 2\n255\n255 0 0  0 255 0\n0 0 255  255 255 255\n"),
        # Wrong or unclear messages
        "err-png-truncated.png": png(64, 64, 6)[:80],
        "err-png-truncated-in-idat.png": png(64, 64, 6)[:-30],
        "err-png-no-iend.png": png(8, 8)[:-12],
        "err-gif-named-png.png": b"GIF89a\x01\x00\x01\x00\x80\x00\x00\x00\x00\x00\xff\xff\xff!\xf9\x04\x01\x00\x00\x00\x00,"
                                 b"\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02D\x01\x00;",
        "err-empty.png": b"",
        "err-text.png": b"this is text, not pixels\n",
        # UBSan inside stb_image
        "err-bmp-height-int-min.bmp": bmp(2, -2147483648, header_only=True),
        "err-bmp-width-int-min.bmp": bmp(-2147483648, 2, header_only=True),
        "err-bmp-truncated.bmp": bmp(40, 40)[:300],
        "err-bmp-rle8.bmp": bmp(4, 4, 8)[:30] + struct.pack("<I", 1) + bmp(4, 4, 8)[34:],
        "err-tga-truncated.tga": tga(16, 16)[:100],
        "err-jpg-arithmetic.jpg": floor[:jpeg_frame_offset(floor) + 1] + b"\xc9" + floor[jpeg_frame_offset(floor) + 2:],
        "ok-jpg-floor.jpg": floor,
        # Found by fuzz-heightmap (issue 14's 10-minute run): a scan that names component 1 three
        # times with different AC tables; stb_image keeps the last choice for all three, read past
        # the data and shifted by 32 (UBSan, stb_image.h:2065).
        "err-jpg-scan-names-a-component-three-times.jpg": jpeg_scan_repeats_component(),
    }
    huge_convex = obj_polygon(100000)
    objs = {
        # Hangs: a face with 100,000 corners
        "ok-convex-100000-corners.obj": huge_convex,
        "ok-convex-100000-corners-with-normals.obj": obj_polygon(100000, normals=True),
        "err-star-100000-corners.obj": obj_polygon(100000, star=True),
        "ok-star-64-corners.obj": obj_polygon(64, star=True),
        "ok-convex-40000-corners-4-decimals.obj": obj_polygon(40000, digits=4),
        "err-winds-twice-1000-corners.obj": obj_polygon(1000, turns=2),
        "ok-winds-twice-60-corners.obj": obj_polygon(60, turns=2),
        "err-star-66-corners.obj": obj_polygon(66, star=True),
        # tinyobjloader's `t` tag allocated what its counts asked for.
        "ok-t-tag-huge-counts.obj": TRIANGLE + "t crease 2000000000/2000000000/0\nf 1 2 3\n",
        # Garbage accepted
        "ok-vn-3e38.obj": TRIANGLE + "vn 3e38 3e38 3e38\nf 1//1 2//1 3//1\n",
        "ok-vn-zero.obj": TRIANGLE + "vn 0 0 0\nf 1//1 2//1 3//1\n",
        "ok-huge-triangle-no-normals.obj": "v -3e38 -3e38 0\nv 3e38 -3e38 0\nv 0 3e38 0\nf 1 2 3\n",
        "ok-tiny-triangle-no-normals.obj": "v 0 0 0\nv 1e-30 0 0\nv 0 1e-30 0\nf 1 2 3\n",
        "err-face-repeats-corners.obj": TRIANGLE + "f 1 2 3\nf 1 2 3 1 2 3\n",
        "err-quad-repeats-a-corner.obj": TRIANGLE + "f 1 2 3 1\n",
        "ok-material-values-out-of-range.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl m\nf 1 2 3\n" + MTL +
                                               "newmtl m\nKd 5 -3 1e30\nKa -1\nKs 2 2 2\nNs -50\n",
        # Valid files refused
        "ok-utf8-bom.obj": "\ufeff" + TRIANGLE + "f 1 2 3\n",
        "ok-cr-only.obj": (TRIANGLE + "f 1 2 3\n").replace("\n", "\r"),
        "ok-crlf.obj": (TRIANGLE + "f 1 2 3\n").replace("\n", "\r\n"),
        "ok-usemtl-with-spaces.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl old  wood\nf 1 2 3\n" + MTL +
                                     "newmtl old  wood\nKd 0.5 0.4 0.3\n",
        # Wrong or unclear messages
        "err-utf16-le.obj": (TRIANGLE + "f 1 2 3\n").encode("utf-16"),
        "err-utf16-be-no-mark.obj": (TRIANGLE + "f 1 2 3\n").encode("utf-16-be"),
        "err-usemtl-undefined-with-spaces.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl old wood\nf 1 2 3\n" + MTL +
                                                "newmtl old\n",
        "err-index-99999999999.obj": TRIANGLE + "f 1 2 99999999999\n",
        "err-index-past-long-long.obj": TRIANGLE + "f 1 2 999999999999999999999999999\n",
        "err-index-negative-huge.obj": TRIANGLE + "f 1 2 -99999999999\n",
        "err-nul-byte.obj": "v 0 0 0\nv 1 0\0 0\nv 0 1 0\nf 1 2 3\n",
        "err-no-faces.obj": TRIANGLE,
        "err-empty.obj": "",
        "err-binary.obj": bytes(range(256)) * 4,
        "err-long-word.obj": "v " + "1" * 100000 + "x 0 0\n",
        "err-mtl-binary.obj": "mtllib m.mtl\n" + TRIANGLE + "f 1 2 3\n" + MTL + "newmtl a\nKd \x00\xff\x1b[31m\n",
    }
    return objs, images


MD2_HEADER = "<17i"  # ident, version, skinwidth, skinheight, framesize, num_skins, num_vertices, num_st,
                     # num_tris, num_glcmds, num_frames, ofs_skins, ofs_st, ofs_tris, ofs_frames, ofs_glcmds, ofs_end
MD2_FIELDS = ("ident", "version", "skinwidth", "skinheight", "framesize", "num_skins", "num_vertices", "num_st",
              "num_tris", "num_glcmds", "num_frames", "ofs_skins", "ofs_st", "ofs_tris", "ofs_frames", "ofs_glcmds",
              "ofs_end")


def md2(frames=("stand1", "stand2", "run1", "run2", "run3", "pain"), vertices=4, skin=(64, 32), glcmds=True, **patch):
    """A small valid MD2 file (a tetrahedron whose vertices move from frame to frame), then
    `patch`: header fields by name (num_frames=513), or frame_name_bytes / normal_index /
    triangle_vertex / triangle_st / scale_y for the first spot of each."""
    st = [(i * 9 + 1, i * 5 + 2) for i in range(6)]
    tris = [((0, 2, 1), (0, 1, 2)), ((0, 1, 3), (1, 2, 3)), ((1, 2, 3), (2, 3, 4)), ((0, 3, 2), (3, 4, 5))]
    skins = [b"models/test/skin.pcx"]
    framesize = 40 + 4 * vertices
    body_skins = b"".join(name.ljust(64, b"\0") for name in skins)
    body_st = b"".join(struct.pack("<hh", s, t) for s, t in st)
    body_tris = b"".join(struct.pack("<6H", *v, *t) for v, t in tris)
    body_frames = b""
    for index, name in enumerate(frames):
        scale = (1 / 255, 1 / 255, 1 / 255)
        if index == 0 and "scale_y" in patch:
            scale = (scale[0], patch["scale_y"], scale[2])
        name_bytes = patch["frame_name_bytes"] if index == 0 and "frame_name_bytes" in patch else name.encode().ljust(16, b"\0")
        body_frames += struct.pack("<6f", *scale, 0.0, 0.1 * index, 0.0) + name_bytes
        for v in range(vertices):
            normal = patch["normal_index"] if index == 0 and v == 0 and "normal_index" in patch else (index * 7 + v * 31) % 162
            body_frames += bytes(((v * 80 + index * 9) & 255, (v * 50) & 255, (v * 120 + index) & 255, normal))
    if "triangle_vertex" in patch:
        body_tris = struct.pack("<H", patch["triangle_vertex"]) + body_tris[2:]
    if "triangle_st" in patch:
        body_tris = body_tris[:6] + struct.pack("<H", patch["triangle_st"]) + body_tris[8:]
    body_gl = struct.pack("<i", 0) if glcmds else b""
    header = dict(ident=844121161, version=8, skinwidth=skin[0], skinheight=skin[1], framesize=framesize,
                  num_skins=len(skins), num_vertices=vertices, num_st=len(st), num_tris=len(tris),
                  num_glcmds=1 if glcmds else 0, num_frames=len(frames))
    header["ofs_skins"] = 68
    header["ofs_st"] = header["ofs_skins"] + len(body_skins)
    header["ofs_tris"] = header["ofs_st"] + len(body_st)
    header["ofs_frames"] = header["ofs_tris"] + len(body_tris)
    header["ofs_glcmds"] = header["ofs_frames"] + len(body_frames)
    header["ofs_end"] = header["ofs_glcmds"] + len(body_gl)
    for name in MD2_FIELDS:
        if name in patch:
            header[name] = patch[name]
    return struct.pack(MD2_HEADER, *(header[name] for name in MD2_FIELDS)) + body_skins + body_st + body_tris + \
        body_frames + body_gl


def md2_seeds():
    return {
        "tetrahedron.md2": md2(),
        "one-frame.md2": md2(frames=("base",)),
        "no-glcmds.md2": md2(glcmds=False),
        "many-vertices.md2": md2(vertices=40),
    }


def md2_regression():
    good = md2()
    header = dict(zip(MD2_FIELDS, struct.unpack(MD2_HEADER, good[:68])))
    cut = header["ofs_frames"] + 2 * header["framesize"] + 10
    return {
        "ok-frames-named-without-digits.md2": md2(frames=("stand", "walk", "walk", "pain")),
        "ok-trailing-bytes-after-end.md2": good + b"trailing",
        "err-empty.md2": b"",
        "err-truncated-header.md2": good[:40],
        "err-truncated-file.md2": good[:-10],
        "err-truncated-frame-block.md2": md2(num_glcmds=0, ofs_end=cut)[:cut],
        "err-magic-idp3.md2": b"IDP3" + good[4:],
        "err-version-7.md2": md2(version=7),
        "err-negative-vertices.md2": md2(num_vertices=-1),
        "err-negative-frames-int-min.md2": md2(num_frames=-2147483648),
        "err-negative-triangles.md2": md2(num_tris=-4),
        "err-negative-glcmds.md2": md2(num_glcmds=-1),
        "err-frames-513.md2": md2(num_frames=513),
        "err-vertices-2049.md2": md2(num_vertices=2049, framesize=40 + 4 * 2049),
        "err-skins-33.md2": md2(num_skins=33),
        "err-zero-vertices.md2": md2(num_vertices=0, framesize=40),
        "err-zero-frames.md2": md2(num_frames=0),
        "err-st-offset-past-end.md2": md2(ofs_st=1000000000),
        "err-tris-overlap-end.md2": md2(ofs_tris=len(good) - 20),
        "err-skins-offset-negative.md2": md2(ofs_skins=-68),
        "err-tris-offset-in-header.md2": md2(ofs_tris=8),
        "err-frames-offset-int-max.md2": md2(ofs_frames=2147483647),
        "err-glcmds-offset-int-max.md2": md2(ofs_glcmds=2147483647),
        "err-end-past-file.md2": md2(ofs_end=2147483647),
        "err-end-negative.md2": md2(ofs_end=-1),
        "err-frame-size-mismatch.md2": md2(framesize=60),
        "err-triangle-vertex-past-vertices.md2": md2(triangle_vertex=4),
        "err-triangle-st-past-texcoords.md2": md2(triangle_st=6),
        "err-normal-index-162.md2": md2(normal_index=162),
        "err-normal-index-255.md2": md2(normal_index=255),
        "err-skin-width-zero.md2": md2(skin=(0, 32)),
        "err-skin-height-negative.md2": md2(skin=(64, -5)),
        "err-scale-infinite.md2": md2(scale_y=float("inf")),
        "err-scale-nan.md2": md2(scale_y=float("nan")),
        "err-frame-name-without-nul.md2": md2(frame_name_bytes=b"a" * 16),
        "err-frame-name-control-byte.md2": md2(frame_name_bytes=b"ru\nn1".ljust(16, b"\0")),
        "err-frame-name-high-byte.md2": md2(frame_name_bytes=b"run\xff".ljust(16, b"\0")),
    }


CROWD_EXPLORE = """  <type name="explorer" model="explorer.md2" skin="explorer.png" scale="0.05" speed="2" sight="6"
        radius="0.5" behaviour="explore"/>
  <behaviour name="explore" kind="fsm" initial="search">
    <state name="home" animation="stand" speed="0">
      <drop/><stop/>
      <transition to="search"><time-in-state seconds="0.5"/></transition>
    </state>
    <state name="search">
      <wander turn="45"/><follow-crumbs/>
      <transition to="carry"><sees-sample/><not><carrying/></not></transition>
      <transition to="flee"><near type="hunter" distance="2.5"/></transition>
      <transition to="search"><blocked ahead="2"/><chance per-step="0.25"/></transition>
    </state>
    <state name="carry" speed="0.8">
      <seek target="sample"/><pick-up/><seek target="base"/><drop-crumb/>
      <transition to="home"><at-base distance="3"/><carrying/></transition>
    </state>
    <state name="flee">
      <flee from="hunter"/><seek target="crumb"/><pick-up-crumb/>
      <transition to="search"><not><sees type="hunter"/></not></transition>
      <transition to="search"><message name="all-clear"/><smells-crumb/></transition>
      <transition to="home"/>
    </state>
  </behaviour>
"""
CROWD_HUNT = """  <type name="hunter" model="hunter.md2" skin="hunter.png" behaviour="hunt"/>
  <behaviour name="hunt" kind="subsumption">
    <layer name="chase" animation="attack" speed="1.5">
      <when><sees type="explorer"/><not><always/></not></when>
      <seek target="explorer"/><attack type="explorer"/><send message="all-clear" radius="6"/>
    </layer>
    <layer name="roam"><wander/><send message="here"/></layer>
  </behaviour>
"""
CROWD_PLACES = """  <ground collision="collision.png" height="height.png" min="-20 -10" max="20 10"
          height-min="-1" height-max="3" scenery="terrain"/>
  <base x="0" z="10" radius="2"/>
  <base x="5" z="-5"/>
  <samples count="40" x="0" z="-8" radius="6"/>
  <spawn type="explorer" count="20" x="0" z="10" radius="2" team="1"/>
  <spawn type="hunter" count="2" x="1" z="2"/>
"""


def crowd_world(inside="", places=CROWD_PLACES, attributes=' seed="7" step="0.05"'):
    return "<world%s>\n%s%s%s%s</world>\n" % (attributes, CROWD_EXPLORE, CROWD_HUNT, places, inside)


def crowd_xml_seeds():
    return {
        "explorers-and-hunters.xml": '<?xml version="1.0" encoding="UTF-8"?>\n<!-- lab 10 -->\n' + crowd_world(),
        "small.xml": '<world><ground collision="c.png"/><type name="a" model="a.md2" skin="a.png" behaviour="b"/>'
                     '<behaviour name="b" kind="fsm"><state name="s"><wander/></state></behaviour>'
                     '<spawn type="a" count="3" x="0" z="0"/></world>',
    }


def crowd_xml_regression():
    state = lambda inner: '<behaviour name="b" kind="fsm"><state name="s">%s</state></behaviour>\n' % inner
    layer = lambda when: '<behaviour name="b" kind="subsumption"><layer name="l"><when>%s</when></layer></behaviour>\n' % when
    return {
        "ok-defaults.xml": crowd_world(attributes=""),
        "ok-not-not.xml": crowd_world(layer("<not><not><carrying/></not></not>")),
        "ok-crlf-and-bom.xml": "\ufeff" + crowd_world().replace("\n", "\r\n"),
        "ok-doctype-skipped.xml": '<!DOCTYPE world [<!ENTITY e "x">]>\n' + crowd_world(),
        "err-empty.xml": "",
        "err-binary.xml": bytes(range(256)),
        "err-malformed.xml": crowd_world().replace("</world>", "</wrold>"),
        "err-unclosed-attribute.xml": '<world seed="1>\n',
        "err-wrong-root.xml": "<agents/>\n",
        "err-two-roots.xml": crowd_world() + "<world/>\n",
        "err-unknown-element.xml": crowd_world('  <wall x="1"/>\n'),
        "err-unknown-attribute.xml": crowd_world('  <base x="0" z="0" radus="2"/>\n'),
        "err-unknown-condition.xml": crowd_world(layer("<hungry/>")),
        "err-text-in-element.xml": crowd_world("  <base x=\"0\" z=\"0\">here</base>\n"),
        "err-missing-attribute.xml": crowd_world('  <spawn count="3" x="0" z="0"/>\n'),
        "err-speed-with-unit.xml": crowd_world('  <type name="t" model="m" skin="s" speed="1.5m" behaviour="hunt"/>\n'),
        "err-nan.xml": crowd_world('  <base x="nan" z="0"/>\n'),
        "err-inf.xml": crowd_world('  <base x="0" z="-inf"/>\n'),
        "err-empty-number.xml": crowd_world('  <base x="" z="0"/>\n'),
        "err-hex-number.xml": crowd_world(attributes=' step="0x1"'),
        "err-step-underflows-to-0.xml": crowd_world(attributes=' step="1e-50"'),
        "err-step-above-1.xml": crowd_world(attributes=' step="2"'),
        "err-seed-past-32-bits.xml": crowd_world(attributes=' seed="4294967296"'),
        "err-seed-negative.xml": crowd_world(attributes=' seed="-1"'),
        "err-count-not-whole.xml": crowd_world('  <samples count="1.5" x="0" z="0"/>\n'),
        "err-count-past-int64.xml": crowd_world('  <samples count="99999999999999999999999" x="0" z="0"/>\n'),
        "err-chance-above-1.xml": crowd_world(layer('<chance per-step="1.5"/>')),
        "err-min-not-pair.xml": crowd_world(places=CROWD_PLACES.replace('min="-20 -10"', 'min="1 2 3"')),
        "err-min-equals-max.xml": crowd_world(places=CROWD_PLACES.replace('min="-20 -10"', 'min="20 -10"')),
        "err-height-max-below-min.xml": crowd_world(places=CROWD_PLACES.replace('height-max="3"', 'height-max="-2"')),
        "err-scenery-unknown.xml": crowd_world(places=CROWD_PLACES.replace("terrain", "forest")),
        "err-no-ground.xml": crowd_world(places='  <spawn type="hunter" count="2" x="1" z="2"/>\n'),
        "err-no-spawn.xml": crowd_world(places=CROWD_PLACES.split("  <spawn")[0]),
        "err-two-grounds.xml": crowd_world('  <ground collision="d.png"/>\n'),
        "err-unknown-state.xml": crowd_world(state('<transition to="sleep"/>')),
        "err-unknown-initial.xml": crowd_world('<behaviour name="b" kind="fsm" initial="x"><state name="s"/></behaviour>\n'),
        "err-no-states.xml": crowd_world('<behaviour name="b" kind="fsm"></behaviour>\n'),
        "err-no-layers.xml": crowd_world('<behaviour name="b" kind="subsumption"/>\n'),
        "err-unknown-kind.xml": crowd_world('<behaviour name="b" kind="bt"><state name="s"/></behaviour>\n'),
        "err-not-two-conditions.xml": crowd_world(layer("<not><carrying/><always/></not>")),
        "err-not-empty.xml": crowd_world(layer("<not/>")),
        "err-two-whens.xml": crowd_world('<behaviour name="b" kind="subsumption"><layer name="l"><when/><when/></layer></behaviour>\n'),
        "err-unknown-behaviour.xml": crowd_world('  <type name="t" model="m" skin="s" behaviour="dance"/>\n'),
        "err-unknown-type-in-spawn.xml": crowd_world('  <spawn type="ghost" count="1" x="0" z="0"/>\n'),
        "err-unknown-type-in-condition.xml": crowd_world(layer('<near type="ghost" distance="1"/>')),
        "err-unknown-type-in-action.xml": crowd_world(state('<flee from="ghost"/>')),
        "err-duplicate-type.xml": crowd_world('  <type name="hunter" model="m" skin="s" behaviour="hunt"/>\n'),
        "err-duplicate-behaviour.xml": crowd_world('<behaviour name="hunt" kind="subsumption"><layer name="l"/></behaviour>\n'),
        "err-duplicate-state.xml": crowd_world('<behaviour name="b" kind="fsm"><state name="s"/><state name="s"/></behaviour>\n'),
        "err-duplicate-attribute.xml": crowd_world('  <base x="0" x="1" z="0"/>\n'),
        "err-team-without-base.xml": crowd_world(places=CROWD_PLACES.replace('  <base x="5" z="-5"/>\n', "")),
        "err-include-missing.xml": crowd_world('  <include file="missing.xml"/>\n'),
        "err-include-itself.xml": crowd_world('  <include file="fuzz.xml"/>\n'),
        "err-too-many-agents.xml": crowd_world('  <spawn type="hunter" count="999990" x="0" z="0"/>\n'),
        "err-too-many-samples.xml": crowd_world('  <samples count="99970" x="0" z="0"/>\n'),
    }


EDITOR_SCENE = """{
  "stoa_scene": 1,
  "ambient": [0.1, 0.1, 0.1],
  "sun": {"direction": [-0.4, -1, -0.3], "color": [1, 1, 1]},
  "camera": {"target": [0, 0, 0], "distance": 12, "yaw": 30, "pitch": 25},
  "renderer": {"deferred": false, "shadows": true, "pcf": 3, "normal_maps": true, "ssao": false, "debug_view": "final"},
  "crowd_world": "",
  "materials": [
    {"name": "marble", "diffuse": [0.8, 0.8, 0.8], "specular": [0.2, 0.2, 0.2], "shininess": 32,
     "diffuse_map": "acropolis/column_diffuse.png", "normal_map": "", "shader": "editor/lit"}
  ],
  "objects": [
    {"id": 1, "name": "floor", "mesh": "shape:plane", "material": "marble", "position": [0, 0, 0],
     "rotation": [0, 0, 0], "scale": [12, 1, 12]}
  ],
  "lights": [
    {"id": 2, "name": "lamp", "position": [0, 3, 0], "color": [1.5, 1.2, 0.9], "radius": 6, "on": true}
  ]
}
"""


def editor_scene_seeds():
    return {
        "example.json": open(os.path.join(ROOT, "assets", "scenes", "example.json"), "rb").read(),
        "small.json": EDITOR_SCENE,
        "version-only.json": '{"stoa_scene": 1}',
    }


def editor_scene_regression():
    scene = lambda old, new: EDITOR_SCENE.replace(old, new, 1)
    return {
        "ok-keys-in-another-order.json": '{"lights": [], "objects": [], "materials": [], "stoa_scene": 1}',
        "ok-byte-order-mark-and-crlf.json": "\ufeff" + EDITOR_SCENE.replace("\n", "\r\n"),
        "ok-tiny-and-huge-floats.json": scene('"position": [0, 0, 0]', '"position": [1e-45, 3.4028235e38, -0.0]'),
        "ok-float-underflows-to-0.json": scene('"yaw": 30', '"yaw": 1e-60'),
        "ok-escapes-in-names.json": scene('"name": "lamp"', '"name": "l\\u00e4mp \\"one\\" \\\\ \\ud83d\\ude00"'),
        "err-empty.json": "",
        "err-binary.json": bytes(range(256)),
        "err-not-an-object.json": "[1, 2, 3]",
        "err-no-version.json": '{"ambient": [0, 0, 0]}',
        "ok-version-2-field-and-swarm.json": scene('"stoa_scene": 1', '"stoa_scene": 2').replace(
            '"crowd_world"', '"field": {"meshes": ["shape:cube"], "rows": 3}, "light_swarm": {"count": 4}, "crowd_world"'),
        "err-field-rows-0.json": scene('"stoa_scene": 1', '"stoa_scene": 2').replace(
            '"crowd_world"', '"field": {"meshes": ["shape:cube"], "rows": 0}, "crowd_world"'),
        "err-newer-version.json": scene('"stoa_scene": 1', '"stoa_scene": 3'),
        "err-version-past-int64.json": scene('"stoa_scene": 1', '"stoa_scene": 99999999999999999999'),
        "err-version-float.json": scene('"stoa_scene": 1', '"stoa_scene": 1.0'),
        "err-unknown-key.json": scene('"ambient"', '"ambiant"'),
        "err-duplicate-key.json": scene('"yaw": 30,', '"yaw": 30, "yaw": 31,'),
        "err-vec3-of-2.json": scene('"position": [0, 0, 0]', '"position": [0, 0]'),
        "err-vec3-of-strings.json": scene('"position": [0, 0, 0]', '"position": ["0", "0", "0"]'),
        "err-zero-id.json": scene('"id": 1', '"id": 0'),
        "err-id-past-32-bits.json": scene('"id": 1', '"id": 4294967296'),
        "err-id-negative.json": scene('"id": 1', '"id": -1'),
        "err-duplicate-id.json": scene('"id": 2', '"id": 1'),
        "err-unknown-material.json": scene('"material": "marble"', '"material": "granite"'),
        "err-duplicate-material.json": scene('"materials": [', '"materials": [{"name": "marble"},'),
        "err-shininess-0.json": scene('"shininess": 32', '"shininess": 0'),
        "err-radius-negative.json": scene('"radius": 6', '"radius": -6'),
        "err-pcf-4.json": scene('"pcf": 3', '"pcf": 4'),
        "err-float-overflow.json": scene('"yaw": 30', '"yaw": 1e39'),
        "err-double-overflow.json": scene('"yaw": 30', '"yaw": 1e400'),
        "err-nul-in-name.json": scene('"name": "lamp"', '"name": "la\\u0000mp"'),
        "err-lone-surrogate.json": scene('"name": "lamp"', '"name": "\\ud800"'),
        "err-invalid-utf8.json": scene('"name": "lamp"', '"name": "\udcff"').encode("utf-8", "surrogateescape"),
        "err-trailing-comma.json": scene('"on": true}', '"on": true,}'),
        "err-comment.json": "// a scene\n" + EDITOR_SCENE,
        "err-unclosed.json": EDITOR_SCENE[:-3],
        "err-nested-1000-deep.json": '{"stoa_scene": 1, "crowd_world": ' + "[" * 1000 + "]" * 1000 + "}",
        "err-two-values.json": EDITOR_SCENE + "{}",
        "err-nul-then-garbage.json": EDITOR_SCENE + "\0garbage",
        "err-unknown-shape.json": scene('"shape:plane"', '"shape:torus"'),
    }


def write(folder, files):
    os.makedirs(folder, exist_ok=True)
    for name, data in files.items():
        if isinstance(data, str):
            data = data.encode("utf-8")
        with open(os.path.join(folder, name), "wb") as out:
            out.write(data)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    objs, images = seeds()
    write(os.path.join(out, "seeds", "obj"), objs)
    write(os.path.join(out, "seeds", "image"), images)
    write(os.path.join(out, "seeds", "md2"), md2_seeds())
    write(os.path.join(out, "seeds", "crowd_xml"), crowd_xml_seeds())
    write(os.path.join(out, "seeds", "editor_scene"), editor_scene_seeds())
    write(os.path.join(out, "seeds", "sound"), sound_seeds())
    objs, images = regression()
    models = md2_regression()
    write(os.path.join(out, "regression", "obj"), objs)
    write(os.path.join(out, "regression", "image"), images)
    write(os.path.join(out, "regression", "md2"), models)
    worlds = crowd_xml_regression()
    write(os.path.join(out, "regression", "crowd_xml"), worlds)
    scenes = editor_scene_regression()
    write(os.path.join(out, "regression", "editor_scene"), scenes)
    sounds = sound_regression()
    write(os.path.join(out, "regression", "sound"), sounds)
    count = sum(len(files) for files in (objs, images, models, worlds, scenes, sounds))
    print("wrote %d regression files and the seeds to %s" % (count, out))


if __name__ == "__main__":
    main()
