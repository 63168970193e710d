#!/usr/bin/python3
"""Hand-computation aid for golden DJI PSDK v1 frames (psdk_crc.md, NOTES §2).

An independent transcription of the CRC16 and CRC32 that ../shared/spec/psdk_crc.md describes,
computed bit by bit (no table), kept apart from the C++ code under test. Write the 12-byte header
with the two CRC16 bytes left as "?? ??" and the DATA bytes by hand, then run:

    test/data/psdk_frame_crc.py "aa 10 00 01 00 00 01 02 00 00 ?? ??"
    crc16: f2 68   frame: aa 10 00 01 00 00 01 02 00 00 f2 68 bc 0f 4c 90

It prints the CRC16 bytes (low byte first) and the whole frame with CRC16 and CRC32 filled in.
The length field is not computed: write it by hand too, the script checks it.
"""
import sys


def table_msb_first(poly, width):
    """Entry i: i placed in the top byte of a `width`-bit register, shifted 8 times MSB-first."""
    top = 1 << (width - 1)
    mask = (1 << width) - 1
    table = []
    for i in range(256):
        reg = i << (width - 8)
        for _ in range(8):
            reg = ((reg << 1) ^ poly) if reg & top else (reg << 1)
            reg &= mask
        table.append(reg)
    return table


CRC16_TABLE = table_msb_first(0x1021, 16)
CRC32_TABLE = table_msb_first(0x04C11DB7, 32)
assert CRC16_TABLE[1] == 0x1021 and CRC16_TABLE[2] == 0x2042
assert CRC32_TABLE[1] == 0x04C11DB7


def crc16(data):
    crc = 0x3FDE
    for b in data:
        crc = (crc >> 8) ^ CRC16_TABLE[(crc ^ b) & 0xFF]
    return crc


def crc32(data):
    crc = 0xFFFFFFFF
    for b in data:
        crc = (crc >> 8) ^ CRC32_TABLE[(crc ^ b) & 0xFF]
    return crc ^ 0xFFFFFFFF


def main():
    text = " ".join(sys.argv[1:]).replace("??", "00")
    frame = bytearray.fromhex(text)
    if len(frame) < 12 or frame[0] != 0xAA:
        sys.exit("give the frame from SOF (0xAA) to the end of DATA, CRC16 bytes as ?? ??, in hex")
    h16 = crc16(frame[0:10])
    frame[10] = h16 & 0xFF
    frame[11] = h16 >> 8
    c32 = crc32(frame)
    frame += bytes([c32 & 0xFF, (c32 >> 8) & 0xFF, (c32 >> 16) & 0xFF, (c32 >> 24) & 0xFF])
    length = frame[1] | ((frame[2] & 0x03) << 8)
    if length != len(frame):
        print("warning: length field says %d, the frame has %d bytes" % (length, len(frame)))
    print("crc16: %02x %02x   frame: %s" % (h16 & 0xFF, h16 >> 8, " ".join("%02x" % b for b in frame)))


if __name__ == "__main__":
    if len(sys.argv) == 2 and sys.argv[1] == "--self-test":
        assert crc16(b"123456789") == 0xEBEC, hex(crc16(b"123456789"))
        assert crc32(b"123456789") == 0x7EAD5C77, hex(crc32(b"123456789"))
        print("ok")
    else:
        main()
