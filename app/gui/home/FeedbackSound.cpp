#include "app/gui/home/FeedbackSound.h"

#include <QAudioDevice>
#include <QMediaDevices>
#include <QSoundEffect>
#include <QUrl>
#include <QtEndian>
#include <cmath>
#include <numbers>
#include <vector>

namespace armtrack::gui::home {

namespace {

constexpr int kRate = 22050;

struct Note {
  double hz, seconds;  // hz 0: silence
};

// A sine per note with 8 ms fades, so nothing clicks.
std::vector<qint16> synthesise(const std::vector<Note>& notes) {
  std::vector<qint16> pcm;
  for (const Note& n : notes) {
    const int count = static_cast<int>(n.seconds * kRate);
    const int fade = kRate / 125;
    for (int i = 0; i < count; ++i) {
      const double envelope = std::min({1.0, i / double(fade), (count - i) / double(fade)});
      const double v =
          n.hz > 0 ? 0.35 * envelope * std::sin(2 * std::numbers::pi * n.hz * i / kRate) : 0.0;
      pcm.push_back(static_cast<qint16>(std::lround(v * 32767)));
    }
  }
  return pcm;
}

void put32(QByteArray& b, quint32 v) {
  char c[4];
  qToLittleEndian(v, c);
  b.append(c, 4);
}

void put16(QByteArray& b, quint16 v) {
  char c[2];
  qToLittleEndian(v, c);
  b.append(c, 2);
}

}  // namespace

QByteArray FeedbackSound::wav(Cue cue) {
  std::vector<Note> notes;
  switch (cue) {
    case Cue::Reached:
      notes = {{660, 0.11}, {880, 0.11}, {1320, 0.18}};
      break;
    case Cue::Counted:
      notes = {{990, 0.07}};
      break;
    case Cue::Hint:
      notes = {{330, 0.14}, {0, 0.07}, {330, 0.14}};
      break;
  }
  const std::vector<qint16> pcm = synthesise(notes);
  const auto bytes = static_cast<quint32>(pcm.size() * 2);
  QByteArray b;
  b.append("RIFF", 4);
  put32(b, 36 + bytes);
  b.append("WAVEfmt ", 8);
  put32(b, 16);
  put16(b, 1);  // PCM
  put16(b, 1);  // mono
  put32(b, kRate);
  put32(b, kRate * 2);
  put16(b, 2);
  put16(b, 16);
  b.append("data", 4);
  put32(b, bytes);
  for (qint16 s : pcm) put16(b, static_cast<quint16>(s));
  return b;
}

QString FeedbackSound::resource(Cue cue) {
  switch (cue) {
    case Cue::Reached:
      return QStringLiteral(":/home-sounds/reached.wav");
    case Cue::Counted:
      return QStringLiteral(":/home-sounds/counted.wav");
    case Cue::Hint:
      break;
  }
  return QStringLiteral(":/home-sounds/hint.wav");
}

FeedbackSound::FeedbackSound(QObject* parent) : QObject(parent) {
  // No output (a computer without sound, a test's virtual display): stay silent.
  if (QMediaDevices::audioOutputs().isEmpty()) return;
  const QAudioDevice device = QMediaDevices::defaultAudioOutput();
  for (std::size_t i = 0; i < m_effects.size(); ++i) {
    auto* effect = new QSoundEffect(device, this);
    // The shipped cues are built into the program (sounds/, made by sounds/make-sounds.py).
    effect->setSource(QUrl(QStringLiteral("qrc") + resource(static_cast<Cue>(i))));
    effect->setVolume(0.8f);
    m_effects[i] = effect;
  }
}

FeedbackSound::~FeedbackSound() = default;

bool FeedbackSound::available() const {
  for (QSoundEffect* e : m_effects)
    if (!e || e->status() == QSoundEffect::Error) return false;
  return true;
}

void FeedbackSound::play(Cue cue) {
  const auto i = static_cast<std::size_t>(cue);
  ++m_asked[i];
  if (m_muted || !m_effects[i] || m_effects[i]->status() == QSoundEffect::Error) return;
  m_effects[i]->play();
}

}  // namespace armtrack::gui::home
