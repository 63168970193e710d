#!/usr/bin/python3
"""Hand-computation aid for golden test frames.

An independent transcription of the document's crc_accumulate / crc_calculate (section 2.1),
kept apart from the C++ code under test. Write the frame bytes by hand from the document, then
run this to get the two checksum bytes to append (low byte first):

    test/data/frame_crc.py "FD 02 04 01 00 01 01 00 04 00 01 00"
    header_excluded: A2 56    whole_frame: AF 74
"""
import sys


def crc_accumulate(data, crc):
    tmp = (data ^ (crc & 0xFF)) & 0xFF
    tmp = (tmp ^ (tmp << 4)) & 0xFF
    return ((crc >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4)) & 0xFFFF


def crc_calculate(buf):
    crc = 0xFFFF  # X25_INIT_CRC
    for b in buf:
        crc = crc_accumulate(b, crc)
    return crc


def main():
    frame = bytes.fromhex(" ".join(sys.argv[1:]))
    if not frame or frame[0] != 0xFD:
        sys.exit("give the frame from STX to the end of the payload, in hex")
    h = crc_calculate(frame[1:])
    w = crc_calculate(frame)
    print("header_excluded: %02X %02X    whole_frame: %02X %02X" % (h & 0xFF, h >> 8, w & 0xFF, w >> 8))


if __name__ == "__main__":
    main()
