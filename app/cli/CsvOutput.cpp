#include "app/cli/CsvOutput.h"

#include <cerrno>
#include <charconv>
#include <random>
#include <stdexcept>
#include <system_error>

#include "app/cli/Text.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

}  // namespace

CsvOutput::CsvOutput(std::string header, std::optional<fs::path> target, std::ostream* out)
    : m_out(out), m_target(std::move(target)) {
  if (m_target) {
    std::random_device rd;
    const unsigned long long tag = (static_cast<unsigned long long>(rd()) << 32) ^ rd();
    char hex[17];
    const auto r = std::to_chars(hex, hex + 16, tag, 16);
    m_tmp = *m_target;
    m_tmp.replace_filename("." + m_target->filename().string() + ".tmp-" + std::string(hex, r.ptr));
    errno = 0;
    m_file = std::fopen(m_tmp.c_str(), "wb");
    if (!m_file) fail("cannot create temporary file " + inQuotes(m_tmp.string()), errno);
  } else if (!m_out) {
    throw std::invalid_argument("CsvOutput: neither a target file nor an output stream");
  }
  m_buf.reserve(kFlushBytes + 256);
  m_buf = std::move(header);
  m_buf += '\n';
}

CsvOutput::~CsvOutput() {
  if (m_file) std::fclose(m_file);
  if (m_target && !m_committed) {
    std::error_code ec;
    fs::remove(m_tmp, ec);
  }
}

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
    errno = 0;
    if (std::fwrite(m_buf.data(), 1, m_buf.size(), m_file) != m_buf.size())
      fail("write failed", errno);
  } else {
    m_out->write(m_buf.data(), static_cast<std::streamsize>(m_buf.size()));
  }
  m_buf.clear();
}

void CsvOutput::commit() {
  flush();
  if (!m_target) {
    m_out->flush();
    if (!*m_out) throw std::runtime_error("writing to standard output failed");
    m_committed = true;
    return;
  }
  errno = 0;
  if (std::fflush(m_file) != 0) fail("write failed", errno);
  std::FILE* f = m_file;
  m_file = nullptr;
  errno = 0;
  if (std::fclose(f) != 0) fail("closing the file failed", errno);
  std::error_code ec;
  fs::rename(m_tmp, *m_target, ec);
  if (ec) fail("cannot rename " + inQuotes(m_tmp.string()) + " into place: " + ec.message(), 0);
  m_committed = true;
}

void CsvOutput::fail(const std::string& message, int err) const {
  std::string what = m_target->string() + ": " + message;
  if (err != 0) what += ": " + std::generic_category().message(err);
  throw std::runtime_error(what);
}

}  // namespace armtrack::cli
