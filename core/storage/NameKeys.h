// Migration to schema 6: the case-folded keys under which account names, patient codes and
// protocol names are unique (docs/storage.md, "Security").
#pragma once

namespace armtrack::storage {

class Database;

/// Fills users.name_key, patients.code_key and protocols.name_key with nameKey() of each row's
/// name or code and makes each key column UNIQUE. Names that differ only in case cannot all
/// keep their spelling: the oldest row (lowest id) keeps it, each later one gets "-2" (or the
/// next number whose key is free) appended, and the rename is audited ("system", "rename",
/// the old name, the new one). Runs in migration step 6's transaction, after its statements.
void addNameKeys(Database& db);

}  // namespace armtrack::storage
