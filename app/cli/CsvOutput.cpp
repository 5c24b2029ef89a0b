#include "app/cli/CsvOutput.h"

#include <charconv>
#include <stdexcept>

namespace armtrack::cli {

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

}  // namespace

CsvOutput::CsvOutput(std::string header, std::optional<std::filesystem::path> target,
                     std::ostream* out)
    : m_out(out), m_target(std::move(target)) {
  if (m_target) {
    guarded([&] { m_file.emplace(*m_target); });
  } else if (!m_out) {
    throw std::invalid_argument("CsvOutput: neither a target file nor an output stream");
  }
  m_buf.reserve(kFlushBytes + 256);
  m_buf = std::move(header);
  m_buf += '\n';
}

CsvOutput::~CsvOutput() = default;  // an uncommitted file's temporary file goes with m_file

void CsvOutput::row(double t, const double* values, int n) {
  char num[32];
  m_buf.append(num, std::to_chars(num, num + sizeof num, t).ptr);
  for (int k = 0; k < n; ++k) {
    m_buf += ',';
    m_buf.append(num, std::to_chars(num, num + sizeof num, values[k]).ptr);
  }
  m_buf += '\n';
  if (m_buf.size() >= kFlushBytes) flush();
}

void CsvOutput::flush() {
  if (m_buf.empty()) return;
  if (m_file) {
    guarded([&] { m_file->write(m_buf); });
  } else {
    m_out->write(m_buf.data(), static_cast<std::streamsize>(m_buf.size()));
  }
  m_buf.clear();
}

void CsvOutput::commit() {
  flush();
  if (!m_file) {
    m_out->flush();
    if (!*m_out) throw std::runtime_error("writing to standard output failed");
    return;
  }
  guarded([&] { m_file->commit(); });
}

}  // namespace armtrack::cli
