#pragma once
// A record (records/columns.h) as it travels between MPI ranks: its columns' values in column
// order, each as ByteWriter puts its type. Derived from the record's column table, so that a
// column added to the record travels with it.

#include "engine/byte_codec.h"
#include "records/columns.h"

namespace shockmap {

template <typename Row>
void PutRecord(const Row& row, const auto& columns, ByteWriter& out) {
  for (const Column<Row>& c : columns) VisitColumn(c, row, [&](const auto& v) { out.Put(v); });
}

// Throws std::runtime_error on a truncated message.
template <typename Row>
Row GetRecord(ByteReader& in, const auto& columns) {
  Row row;
  for (const Column<Row>& c : columns) VisitColumn(c, row, [&](auto& v) { in.Read(v); });
  return row;
}

}  // namespace shockmap
