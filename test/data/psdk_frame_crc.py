#!/usr/bin/python3
"""Hand-computation aid for golden DJI PSDK v1 frames (docs/psdk.md).

An independent transcription of the CRC16 and CRC32 that docs/psdk.md describes,
computed bit by bit (no table), kept apart from the C++ code under test. Write the 12-byte header
with the two CRC16 bytes left as "?? ??" and the DATA bytes by hand, then run:

    test/data/psdk_frame_crc.py "aa 10 00 01 00 00 01 02 00 00 ?? ??"
    crc16: f2 68   frame: aa 10 00 01 00 00 01 02 00 00 f2 68 bc 0f 4c 90

It prints the CRC16 bytes (low byte first) and the whole frame with CRC16 and CRC32 filled in.
The length field is not computed: write it by hand too, the script checks it.

    test/data/psdk_frame_crc.py --fill test/data/psdk_golden/camera.txt

completes a golden file in place (test/data/psdk_golden/README.md): in each frame written by hand,
the CRC16 bytes and the four CRC32 bytes are "??"; a frame whose header says AES (byte 4 bits
5-7 = 1) has its DATA written in plain, already zero-padded, on a line "P: ..." that becomes a
"# plain DATA: ..." comment and the ciphertext (`openssl enc -aes-128-ecb -nopad`, key MD5(app
name + app id + app key + developer account) of the test credentials, hashlib).
"""
import hashlib
import subprocess
import sys

# The credentials of the bridge tests (test/ros/unit/skyport_bridge_rig.h; a demo key).
TEST_CREDENTIALS = ("k40t_test", "123456", "0123456789abcdef0123456789abcdef", "dev@example.com")


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


def aes_key():
    return hashlib.md5("".join(TEST_CREDENTIALS).encode()).digest()


def encrypt(plain):
    if len(plain) % 16:
        sys.exit("plain DATA of %d bytes: pad it to a multiple of 16 by hand" % len(plain))
    return subprocess.run(["openssl", "enc", "-aes-128-ecb", "-nopad", "-K", aes_key().hex()],
                          input=bytes(plain), stdout=subprocess.PIPE, check=True).stdout


def complete(frame):
    """Fills CRC16 (bytes 10-11) and CRC32 (last 4) of a frame whose placeholders are zero."""
    h16 = crc16(frame[0:10])
    frame[10] = h16 & 0xFF
    frame[11] = h16 >> 8
    c32 = crc32(frame[:-4])
    frame[-4:] = bytes([c32 & 0xFF, (c32 >> 8) & 0xFF, (c32 >> 16) & 0xFF, (c32 >> 24) & 0xFF])
    length = frame[1] | ((frame[2] & 0x03) << 8)
    if length != len(frame):
        sys.exit("length field says %d, the frame has %d bytes: %s" % (length, len(frame), frame.hex(" ")))
    return frame


def fill(path):
    out, block, plain = [], [], None

    def flush():
        nonlocal block, plain
        if not block:
            return
        frame = bytearray.fromhex(" ".join(block).replace("??", "00"))
        if plain is not None:
            if frame[4] >> 5 != 1:
                sys.exit("P: line in a frame whose header does not say AES")
            out.append("# plain DATA: " + " ".join("%02X" % b for b in plain))
            frame = frame[:12] + encrypt(plain) + frame[12:]
        frame = complete(frame)
        for i in range(0, len(frame), 24):
            out.append(" ".join("%02X" % b for b in frame[i:i + 24]))
        block, plain = [], None

    for line in open(path).read().splitlines():
        text = line.strip()
        if text.startswith("P:"):
            plain = bytearray.fromhex(text[2:])
        elif text and not text.startswith("#") and not text.startswith("="):
            block.append(text)
        else:
            flush()
            out.append(line)
    flush()
    open(path, "w").write("\n".join(out) + "\n")


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
    if len(sys.argv) == 3 and sys.argv[1] == "--fill":
        fill(sys.argv[2])
    elif len(sys.argv) == 2 and sys.argv[1] == "--self-test":
        assert crc16(b"123456789") == 0xEBEC, hex(crc16(b"123456789"))
        assert crc32(b"123456789") == 0x7EAD5C77, hex(crc32(b"123456789"))
        print("ok")
    else:
        main()
