#pragma once
// The registered scores (validation/scores.h) into a kind's score row (records/): each score
// into the optional real column of its name.

#include <string>
#include <string_view>

#include "records/columns.h"
#include "validation/scores.h"

namespace shockmap {

// Sets every column of `row` named after a registered score and `suffix` ("err", or
// "err_spread_low" with suffix "_spread_low") to that score's value (NULL when it has none). A
// registered score the row has no column for is not stored by this kind (tests/records_test.cpp
// checks which kinds store which scores).
template <typename Row>
void SetScoreColumns(Row& row, const auto& columns, const ScoreValues& values,
                     std::string_view suffix = "") {
  for (const ScoreDefinition& score : Scores()) {
    if (const auto member = OptionalRealMember(columns, std::string(score.name) += suffix))
      row.*member = values[score.name];
  }
}

}  // namespace shockmap
