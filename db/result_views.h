#pragma once
// The kinds' results views, each declared once (db/result_views.cpp): the tables it joins, the
// columns it showed at schema 15 in their order, and the records it reads. Every other column
// of those records, but those it leaves out, follows in its record's order: a column added to
// a record (docs/architecture.md, "To add a field") is shown with no SQL written. The migrations
// change tables only; the views are written from these declarations whenever a database is
// created or migrated (db/schema.cpp), the kinds' parameter views (db/point_tables.h) after
// them.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "db/sqlite_handle.h"

namespace shockmap {

// A record a results view reads.
struct ViewSource {
  std::string_view alias;                  // Of its table in the view's joins ("sc").
  std::vector<std::string> columns;        // Its record's, in order (ColumnNames).
  std::vector<std::string_view> left_out;  // Those the view does not show.
  std::string_view prefix;  // Of the name a column that follows is shown by ("ref_"), or "".
};

struct ResultView {
  std::string_view name;
  int since = 0;  // The schema version that added it.
  // Its first columns, in order: "alias.column" or "expression AS name".
  std::vector<std::string_view> shown;
  std::vector<ViewSource> sources;
  std::string_view joins;  // What follows FROM.
};

// Every kind's results view, in the order the kinds were added.
std::span<const ResultView> ResultViews();

// The view's names of columns and their expressions, "expression AS name" or "alias.column":
// `shown`, then the other columns of its sources.
std::vector<std::string> ViewColumns(const ResultView& view);

// The CREATE VIEW statement of `view`.
std::string CreateViewSql(const ResultView& view);

// `sql` with each run of white space made one space: two definitions of a view that differ only
// in their layout are the same (earlier versions wrote the views' text by hand).
std::string WithoutLayout(std::string_view sql);

// Drops each declared view (results and parameter views) the database holds; before migrating:
// a view would stop a table's rebuild.
void DropDeclaredViews(Connection& c);

// Writes the results views from their declarations, then each kind's parameter view with the
// paths stored now.
void CreateDeclaredViews(Connection& c);

}  // namespace shockmap
