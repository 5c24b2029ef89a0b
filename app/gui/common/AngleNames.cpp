#include "app/gui/common/AngleNames.h"

#include "ui/AngleTableModel.h"

namespace armtrack::gui {

QString angleName(int index) {
  return ui::angleDisplayName(index);
}

}  // namespace armtrack::gui
