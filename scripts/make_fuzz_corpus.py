#!/usr/bin/python3
"""Writes the seed corpora of the fuzz targets from the hand-written golden frames.

    scripts/make_fuzz_corpus.py OUT_DIR [GOLDEN_DIR]

Reads every test/data/golden/*.txt (format in test/data/golden/README.md), keeps the frames whose
checksum is valid (checked with test/data/frame_crc.py's transcription of the document's
routine) and writes:
  OUT_DIR/fuzz_parser/    each frame alone, the same frame re-checksummed with whole-frame
                          coverage, all frames back to back, and all frames with garbage and
                          false STX bytes between them, in one piece and in small chunks;
  OUT_DIR/fuzz_decoders/  the 3 id bytes of each frame followed by its payload.
fuzz_parser takes its settings from the END of the input (FuzzedDataProvider reads integers
from the back), so each of its seeds ends with a small trailer: chunk sizes, chunk count,
coverage mode.
"""
import glob
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test", "data"))
from frame_crc import crc_calculate  # noqa: E402

HEADER_EXCLUDED, WHOLE_FRAME, AUTO = 0, 1, 2


def golden_frames(golden_dir):
    """The frames of every golden file: hex lines up to an '=' line; '#' lines are comments
    (test/data/golden/README.md)."""
    frames = []
    for path in sorted(glob.glob(os.path.join(golden_dir, "*.txt"))):
        current = bytearray()
        for line in open(path, encoding="utf-8"):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("="):
                if current:
                    frames.append(bytes(current))
                current = bytearray()
            else:
                try:
                    current += bytes.fromhex(line)
                except ValueError:
                    current = bytearray()  # malformed: the golden-file test reports it
    return frames


def checksum_ok(frame):
    if len(frame) < 12 or frame[0] != 0xFD or frame[1] != len(frame) - 12:
        return False
    received = frame[-2] | frame[-1] << 8
    return received in (crc_calculate(frame[1:-2]), crc_calculate(frame[:-2]))


def with_whole_frame_crc(frame):
    crc = crc_calculate(frame[:-2])
    return frame[:-2] + bytes([crc & 0xFF, crc >> 8])


def parser_trailer(coverage, chunks=()):
    """Bytes that fuzz_parser's FuzzedDataProvider reads back as (coverage, chunk sizes)."""
    trailer = bytearray()
    for size in reversed(chunks):  # consumed last-first; each 1..600 in two bytes, MSB last
        offset = size - 1
        trailer += bytes([offset & 0xFF, offset >> 8])
    trailer.append(len(chunks))  # chunk count 0..16
    trailer.append(coverage)
    return bytes(trailer)


def write(directory, name, data):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, name), "wb") as f:
        f.write(data)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    golden_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "test", "data", "golden")
    frames = [f for f in golden_frames(golden_dir) if checksum_ok(f)]
    if not frames:
        sys.exit("no valid golden frames under " + golden_dir)

    parser_dir = os.path.join(out, "fuzz_parser")
    decoders_dir = os.path.join(out, "fuzz_decoders")
    for i, frame in enumerate(frames):
        write(parser_dir, "frame_%03d" % i, frame + parser_trailer(HEADER_EXCLUDED))
        write(parser_dir, "frame_%03d_whole" % i, with_whole_frame_crc(frame) + parser_trailer(AUTO))
        write(decoders_dir, "payload_%03d" % i, frame[7:10] + frame[10:-2])

    rng = random.Random(1)
    stream = b"".join(frames)
    noisy = bytearray()
    for frame in frames:
        noisy += bytes(rng.choice([0xFD, rng.randrange(256)]) for _ in range(rng.randrange(8)))
        noisy += frame
    write(parser_dir, "all_frames", stream + parser_trailer(HEADER_EXCLUDED))
    write(parser_dir, "all_frames_chunked", stream + parser_trailer(AUTO, [1, 7, 33, 255]))
    write(parser_dir, "noisy_frames", bytes(noisy) + parser_trailer(AUTO, [13, 2]))
    print("fuzz corpus: %d golden frames -> %s" % (len(frames), out))


if __name__ == "__main__":
    main()
