"""The sound files of the loaders' regression corpus (make-regression-corpus.py):
the seeds the sound fuzzer starts from, and the files that must load or be
refused. A file damaged past the Ogg checksum test is damaged the way an
attacker would: with every page's checksum fixed after."""

import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def ogg_fix_checksums(data):
    """Every Ogg page's CRC-32 set to match its bytes (RFC 3533): a file damaged the way
    an attacker damages it, past the checksum test."""
    table = []
    for i in range(256):
        r = i << 24
        for _ in range(8):
            r = ((r << 1) ^ 0x04C11DB7) if r & 0x80000000 else r << 1
        table.append(r & 0xFFFFFFFF)
    data = bytearray(data)
    at = 0
    while at + 27 <= len(data):
        size = 27 + data[at + 26] + sum(data[at + 27:at + 27 + data[at + 26]])
        crc = 0
        for i, byte in enumerate(data[at:at + size]):
            byte = 0 if 22 <= i < 26 else byte
            crc = ((crc << 8) & 0xFFFFFFFF) ^ table[((crc >> 24) ^ byte) & 0xFF]
        data[at + 22:at + 26] = struct.pack("<I", crc)
        at += size
    return bytes(data)


def wav(channels=1, rate=22050, bits=16, frames=64, data_size=None):
    block = channels * bits // 8
    samples = bytes((i * 7) & 0xFF for i in range(frames * block))
    size = len(samples) if data_size is None else data_size
    fmt = struct.pack("<HHIIHH", 1, channels, rate, rate * block, block, bits)
    return (b"RIFF" + struct.pack("<I", 4 + 8 + len(fmt) + 8 + len(samples)) + b"WAVE" + b"fmt " +
            struct.pack("<I", len(fmt)) + fmt + b"data" + struct.pack("<I", size) + samples)


def sound_seeds():
    sounds = os.path.join(ROOT, "assets", "sounds")
    files = {name: open(os.path.join(sounds, name), "rb").read() for name in ("spark.ogg", "footstep.ogg")}
    files["mono16.wav"] = wav()
    files["stereo8.wav"] = wav(channels=2, bits=8)
    return files


def sound_regression():
    spark = open(os.path.join(ROOT, "assets", "sounds", "spark.ogg"), "rb").read()
    setup = spark.find(b"\x05vorbis")
    bomb = bytearray(spark)
    bomb[setup + 13:setup + 16] = b"\xff\xff\xff"   # the first codebook: 16,777,215 entries
    return {
        "ok-spark.ogg": spark,
        "ok-mono16.wav": wav(),
        "err-codebook-of-16-million-entries.ogg": ogg_fix_checksums(bytes(bomb)),
        "err-cut.ogg": spark[:len(spark) - 100],
        "err-empty.ogg": b"",
        "err-wav-data-past-the-end.wav": wav(data_size=1 << 30),
        "err-wav-three-channels.wav": wav(channels=3),
        "err-wav-rate-of-1-hz.wav": wav(rate=1),
    }
