#pragma once
// The registered scores (validation/scores.h) into a kind's score row (records/): each score
// into the optional real column of its name.

#include "records/columns.h"
#include "validation/scores.h"

namespace shockmap {

// Sets every column of `row` named after a registered score to that score's value (NULL when it
// has none). A registered score the row has no column for is not stored by this kind
// (tests/records_test.cpp checks which kinds store which scores).
template <typename Row>
void SetScoreColumns(Row& row, const auto& columns, const ScoreValues& values) {
  for (const ScoreDefinition& score : Scores()) {
    if (const auto member = OptionalRealMember(columns, score.name))
      row.*member = values[score.name];
  }
}

}  // namespace shockmap
