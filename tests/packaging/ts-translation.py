"""Prints the finished translation of one source text in a Qt Linguist .ts file.

    ts-translation.py FILE.ts CONTEXT SOURCE

Exits 1, printing nothing, when the context has no such message or its translation is empty or
unfinished. The install test (in-root-checks.sh) reads the words a translated report must show
from here, so the truth is the translators' file, not a copy in the test.
"""
import sys
import xml.etree.ElementTree as ET


def main() -> int:
    path, context_name, source = sys.argv[1:4]
    for context in ET.parse(path).getroot().iter("context"):
        if context.findtext("name") != context_name:
            continue
        for message in context.iter("message"):
            if message.findtext("source") != source:
                continue
            translation = message.find("translation")
            if translation is None or not (translation.text or "").strip():
                return 1
            if translation.get("type") in ("unfinished", "vanished", "obsolete"):
                return 1
            print(translation.text)
            return 0
    return 1


if __name__ == "__main__":
    sys.exit(main())
