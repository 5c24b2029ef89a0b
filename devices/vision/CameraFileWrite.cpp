// writeCameraFile lives apart from the parser: it needs armtrack_core (AtomicFile), which the fuzz
// build does not have.
#include "core/io/AtomicFile.h"
#include "devices/vision/CameraFile.h"

namespace armtrack::devices::webcam {

void writeCameraFile(const std::filesystem::path& path, const CameraFile& file) {
  try {
    AtomicFile out(path);
    out.write(toJson(file));
    out.commit();
  } catch (const AtomicFileError& e) {
    throw CameraFileError(e.what());
  }
}

}  // namespace armtrack::devices::webcam
