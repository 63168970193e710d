#!/usr/bin/python3
"""Builds test/data/sample_capture.bin, a capture to try `k40t decode` and `k40t monitor` on.

The capture is the frames of every test/data/golden/*.txt file (sorted by file name, frames in
file order) as a byte stream that a real serial line could have produced: between the good
frames it interleaves, in turn, line-noise bytes, false STX bytes (one with an impossible LEN,
one whose LEN swallows the next good frame), a truncated copy of the previous frame and a
corrupted copy of it (one payload bit flipped, so its checksum fails). A correct parser recovers
every good frame and nothing else; test/unit/test_k40t_tool.cpp checks that with `k40t
decode`, and that the committed capture is what this script produces now.

usage: scripts/make_sample_capture.py [--golden DIR] [--output FILE]
"""
import argparse
import glob
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

NOISE = bytes([0x00, 0x55, 0xAA, 0x13, 0x37, 0xFF, 0x80, 0x01])  # no 0xFD: STX only on purpose
STX = 0xFD


def golden_frames(path):
    """The frames of one golden file (format: test/data/golden/README.md)."""
    frames, current = [], bytearray()
    with open(path) as f:
        for number, line in enumerate(f, 1):
            text = line.strip()
            if not text or text.startswith('#'):
                continue
            if text.startswith('='):
                if not current:
                    sys.exit('%s:%d: "=" line without a frame before it' % (path, number))
                frames.append(bytes(current))
                current = bytearray()
                continue
            try:
                current += bytes.fromhex(text)
            except ValueError as e:
                sys.exit('%s:%d: %s' % (path, number, e))
    if current:
        sys.exit('%s: the last frame has no "=" line' % path)
    return frames


def corrupted(frame):
    """A copy with one bit flipped in the payload (or in the message id if there is none)."""
    copy = bytearray(frame)
    copy[10 if len(frame) > 12 else 7] ^= 0x01
    return bytes(copy)


def build(frames):
    out = bytearray(NOISE[:4])  # the line was not idle when the capture started
    for i, frame in enumerate(frames):
        out += frame
        kind = i % 4
        if kind == 0:
            out += NOISE
        elif kind == 1:
            out += bytes([STX, 0xFF])  # false STX: LEN 255 > 243, rejected at once
            out += bytes([STX, 0x03, 0x42])  # false STX: its LEN reaches into the next frame
        elif kind == 2:
            out += frame[:len(frame) // 2]  # truncated: the next frame's STX interrupts it
        else:
            out += corrupted(frame)
    out += NOISE[4:]
    return bytes(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--golden', default=os.path.join(ROOT, 'test', 'data', 'golden'))
    parser.add_argument('--output', default=os.path.join(ROOT, 'test', 'data', 'sample_capture.bin'))
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.golden, '*.txt')))
    if not files:
        sys.exit('no golden files in %s' % args.golden)
    frames = [frame for path in files for frame in golden_frames(path)]
    capture = build(frames)
    with open(args.output, 'wb') as f:
        f.write(capture)
    print('%s: %d frames from %d files, %d bytes' % (args.output, len(frames), len(files), len(capture)))


if __name__ == '__main__':
    main()
