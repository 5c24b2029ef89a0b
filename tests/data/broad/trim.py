#!/usr/bin/env python3
"""Builds broad.tar.xz from the full BROAD trial CSVs (see README.md).

Usage: trim.py SOURCE_DIR  (a folder with <trial>.csv and <trial>.truth.csv, as converted from
the published .mat files). Writes broad.tar.xz next to this script. Cells are copied as text, so
the test parses exactly the numbers it parsed from the full files.
"""
import io
import pathlib
import sys
import tarfile

TRIALS = [
    "02_undisturbed_slow_rotation_B",
    "07_undisturbed_fast_rotation_B",
    "16_undisturbed_fast_translation_B",
]
HEADER = "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z,qw,qx,qy,qz,movement"


def lines(path):
    text = path.read_text()
    return text.rstrip("\n").split("\n")[1:]  # without the header


def trim(source, trial):
    imu = lines(source / f"{trial}.csv")
    truth = lines(source / f"{trial}.truth.csv")
    assert len(imu) == len(truth), trial
    rows = []
    for a, b in zip(imu, truth):
        a, b = a.split(","), b.split(",")
        assert a[0] == b[0], (trial, a[0], b[0])  # one clock for both files
        moving = b[5] == "1"
        rows.append(a + (b[1:5] if moving else ["nan"] * 4) + [b[5]])
    # Nothing after the last scored sample changes the score: drop it.
    last = max(i for i, r in enumerate(rows) if r[-1] == "1")
    return "\n".join([HEADER] + [",".join(r) for r in rows[: last + 1]]) + "\n"


def main():
    source = pathlib.Path(sys.argv[1])
    out = pathlib.Path(__file__).with_name("broad.tar.xz")
    with tarfile.open(out, "w:xz", preset=9 | 0x80000000) as tar:  # xz -9e
        for trial in TRIALS:
            data = trim(source, trial).encode()
            info = tarfile.TarInfo(f"{trial}.csv")
            info.size = len(data)
            info.mode = 0o644
            tar.addfile(info, io.BytesIO(data))
    print(out, out.stat().st_size, "bytes")


if __name__ == "__main__":
    main()
