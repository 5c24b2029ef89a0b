#!/usr/bin/env python3
"""Writes the home window's feedback cues (16-bit mono PCM WAV, 22050 Hz) into this folder.

The same tones as FeedbackSound::wav() (app/gui/home/FeedbackSound.cpp); test_feedback_sound
checks that the shipped files are what that function makes. Run: python3 make-sounds.py
"""
import math
import os
import struct

RATE = 22050
CUES = {
    "reached": [(660, 0.11), (880, 0.11), (1320, 0.18)],  # a rising chime: the target reached
    "counted": [(990, 0.07)],                              # a short tick: a repetition counted
    "hint": [(330, 0.14), (0, 0.07), (330, 0.14)],         # a low double tone: a hint
}


def lround(x):
    return int(math.floor(x + 0.5)) if x >= 0 else int(math.ceil(x - 0.5))


def synthesise(notes):
    pcm = []
    for hz, seconds in notes:
        count = int(seconds * RATE)
        fade = RATE // 125  # 8 ms fades, so nothing clicks
        for i in range(count):
            envelope = min(1.0, i / fade, (count - i) / fade)
            v = 0.35 * envelope * math.sin(2 * math.pi * hz * i / RATE) if hz > 0 else 0.0
            pcm.append(lround(v * 32767))
    return pcm


def wav(pcm):
    data = struct.pack("<%dh" % len(pcm), *pcm)
    return (b"RIFF" + struct.pack("<I", 36 + len(data)) + b"WAVEfmt " +
            struct.pack("<IHHIIHH", 16, 1, 1, RATE, RATE * 2, 2, 16) + b"data" +
            struct.pack("<I", len(data)) + data)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, notes in CUES.items():
        with open(os.path.join(here, name + ".wav"), "wb") as f:
            f.write(wav(synthesise(notes)))
