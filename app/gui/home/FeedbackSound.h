// The audible half of the exercise feedback (Qt Multimedia): a rising chime when the target is
// reached, a short tick for a repetition counted, a low double tone for a hint. The tones are WAV
// files shipped in the program's resources (sounds/, made by sounds/make-sounds.py; wav() makes
// the same and the test holds the files to it). On a computer without sound (no audio output, no
// sound server) it stays silent and says so through available(); nothing fails and nothing is
// printed.
#pragma once

#include <QObject>
#include <array>
#include <cstdint>

class QSoundEffect;

namespace armtrack::gui::home {

class FeedbackSound : public QObject {
  Q_OBJECT
 public:
  enum class Cue { Reached, Counted, Hint };

  explicit FeedbackSound(QObject* parent = nullptr);
  ~FeedbackSound() override;

  /// An audio output exists and the tones could be loaded.
  bool available() const;
  void setMuted(bool muted) { m_muted = muted; }
  bool muted() const { return m_muted; }
  /// Plays the cue (when available and not muted); asked() counts every request.
  void play(Cue cue);
  std::uint64_t asked(Cue cue) const { return m_asked[static_cast<std::size_t>(cue)]; }

  /// The cue's tone as a WAV file (16-bit mono PCM, 22050 Hz), as the shipped files hold it.
  static QByteArray wav(Cue cue);
  /// The shipped file of the cue (a resource path, ":/home-sounds/...").
  static QString resource(Cue cue);

 private:
  std::array<QSoundEffect*, 3> m_effects{};
  std::array<std::uint64_t, 3> m_asked{};
  bool m_muted = false;
};

}  // namespace armtrack::gui::home
