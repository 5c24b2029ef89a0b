// Database::afterTransaction: work that must outlive a rolled-back transaction.
#include "core/storage/Database.h"

namespace armtrack::storage {

void Database::afterTransaction(std::function<void()> work) {
  if (!m_inTransaction) {
    work();
    return;
  }
  m_afterTransaction.push_back(std::move(work));
}

void Database::runAfterTransaction() noexcept {
  if (m_inTransaction || m_afterTransaction.empty()) return;
  // Taken out first: the work may run transactions of its own, which end here again.
  const std::vector<std::function<void()>> work = std::exchange(m_afterTransaction, {});
  for (const auto& w : work) {
    try {
      w();
    } catch (...) {  // NOLINT(bugprone-empty-catch): see afterTransaction()
    }
  }
}

}  // namespace armtrack::storage
