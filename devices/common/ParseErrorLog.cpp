#include "devices/common/ParseErrorLog.h"

#include <utility>

namespace armtrack::devices {

void ParseErrorLog::report(std::uint64_t offset, std::string message) {
  ++m_count;
  if (m_capacity == 0) return;
  if (m_recent.size() == m_capacity) m_recent.pop_front();
  m_recent.push_back({offset, std::move(message)});
}

void ParseErrorLog::clear() {
  m_count = 0;
  m_recent.clear();
}

}  // namespace armtrack::devices
