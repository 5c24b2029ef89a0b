// The home window's audible cues: the WAV files built into the program are well-formed 16-bit
// mono PCM at 22050 Hz, hold the tones FeedbackSound::wav() describes (sample for sample, to
// one step of rounding), and sound as meant: the "target reached" chime rises 660 -> 880 ->
// 1320 Hz, measured from the samples' zero crossings; the hint has its silent gap. Playing on a
// machine without an audio output is silent and counted.
#include <QFile>
#include <QTest>
#include <QtEndian>
#include <cmath>

#include "app/gui/home/FeedbackSound.h"

using armtrack::gui::home::FeedbackSound;
using Cue = FeedbackSound::Cue;

namespace {

struct Wav {
  quint16 format = 0, channels = 0, bits = 0;
  quint32 rate = 0;
  std::vector<qint16> samples;
};

// Parses the canonical 44-byte header written by make-sounds.py; throws on anything else.
Wav parse(const QByteArray& b) {
  if (b.size() < 44 || !b.startsWith("RIFF") || b.mid(8, 8) != "WAVEfmt " || b.mid(36, 4) != "data")
    throw std::runtime_error("not a canonical WAV file");
  const auto u32 = [&](int at) { return qFromLittleEndian<quint32>(b.constData() + at); };
  const auto u16 = [&](int at) { return qFromLittleEndian<quint16>(b.constData() + at); };
  if (u32(4) != static_cast<quint32>(b.size() - 8)) throw std::runtime_error("RIFF size wrong");
  Wav w;
  w.format = u16(20);
  w.channels = u16(22);
  w.rate = u32(24);
  w.bits = u16(34);
  const quint32 bytes = u32(40);
  if (bytes != static_cast<quint32>(b.size() - 44) || bytes % 2)
    throw std::runtime_error("data size wrong");
  for (quint32 i = 0; i < bytes; i += 2)
    w.samples.push_back(qFromLittleEndian<qint16>(b.constData() + 44 + i));
  return w;
}

Wav shipped(Cue cue) {
  QFile f(FeedbackSound::resource(cue));
  if (!f.open(QIODevice::ReadOnly)) throw std::runtime_error("no resource");
  return parse(f.readAll());
}

// Frequency from the upward zero crossings between from and to seconds (the fades excluded).
double frequency(const Wav& w, double from, double to) {
  const auto a = static_cast<std::size_t>(from * w.rate), b = static_cast<std::size_t>(to * w.rate);
  std::vector<std::size_t> ups;
  for (std::size_t i = a + 1; i < b; ++i)
    if (w.samples[i - 1] < 0 && w.samples[i] >= 0) ups.push_back(i);
  if (ups.size() < 2) return 0;
  return (ups.size() - 1) * double(w.rate) / double(ups.back() - ups.front());
}

}  // namespace

class TestFeedbackSound : public QObject {
  Q_OBJECT
 private slots:
  void shippedFilesAreTheGeneratedTones() {
    for (Cue cue : {Cue::Reached, Cue::Counted, Cue::Hint}) {
      const Wav w = shipped(cue);
      QCOMPARE(w.format, quint16(1));
      QCOMPARE(w.channels, quint16(1));
      QCOMPARE(w.bits, quint16(16));
      QCOMPARE(w.rate, quint32(22050));
      const Wav made = parse(FeedbackSound::wav(cue));
      QCOMPARE(w.samples.size(), made.samples.size());
      int worst = 0;
      for (std::size_t i = 0; i < w.samples.size(); ++i)
        worst = std::max(worst, std::abs(int(w.samples[i]) - int(made.samples[i])));
      QVERIFY2(worst <= 1, qPrintable(QString::number(worst)));
      // Loud enough to hear, never clipped.
      const auto [lo, hi] = std::minmax_element(w.samples.begin(), w.samples.end());
      QVERIFY(*hi > 10000 && *hi < 12000 && *lo < -10000);
    }
  }

  void theChimeRisesAndTheHintPauses() {
    const Wav reached = shipped(Cue::Reached);
    QCOMPARE(reached.samples.size(), std::size_t(2425 + 2425 + 3969));
    QVERIFY(std::abs(frequency(reached, 0.01, 0.10) - 660) < 15);
    QVERIFY(std::abs(frequency(reached, 0.12, 0.21) - 880) < 15);
    QVERIFY(std::abs(frequency(reached, 0.23, 0.39) - 1320) < 20);
    QVERIFY(std::abs(frequency(shipped(Cue::Counted), 0.01, 0.06) - 990) < 30);
    const Wav hint = shipped(Cue::Hint);
    QVERIFY(std::abs(frequency(hint, 0.01, 0.13) - 330) < 10);
    for (std::size_t i = 3087; i < 3087 + 1543; ++i) QCOMPARE(hint.samples[i], qint16(0));
  }

  void withoutAnOutputItIsSilentAndCounts() {
    FeedbackSound sound;
    sound.play(Cue::Reached);
    sound.play(Cue::Reached);
    sound.setMuted(true);
    sound.play(Cue::Hint);
    QCOMPARE(sound.asked(Cue::Reached), std::uint64_t(2));
    QCOMPARE(sound.asked(Cue::Hint), std::uint64_t(1));
    QCOMPARE(sound.asked(Cue::Counted), std::uint64_t(0));
  }
};

QTEST_MAIN(TestFeedbackSound)
#include "test_feedback_sound.moc"
