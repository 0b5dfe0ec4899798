#pragma once
// The study database schema, versioned by PRAGMA user_version, with forward migrations.

#include "db/migrations.h"
#include "db/sqlite_handle.h"

namespace shockmap {

// PRAGMA application_id of every shockmap database ("SHMP"): tells ours from a foreign file.
inline constexpr int kApplicationId = 0x53484D50;

// Brings a database to kSchemaVersion, all pending migrations in one transaction. A new, empty
// file is initialized. Throws DbError without modifying the file when it is not a shockmap
// database (foreign application id), was written by a newer shockmap (user_version >
// kSchemaVersion), holds a negative user_version or tables that disagree with its version (the
// tables, views and columns of that version must be there, none the next version adds), fails
// PRAGMA quick_check, or holds a view or trigger that is not one this build writes, as it writes
// it (another program's view could make every reader run for ever, a trigger could run inside
// any write).
void MigrateToCurrent(Connection& db);

// The same checks without writing: for read-only connections.
void CheckSchema(Connection& db);

}  // namespace shockmap
