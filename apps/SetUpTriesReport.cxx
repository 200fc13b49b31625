#include "SetUpTriesReport.h"

#include "sequence/PrintSequencer.h"

#include <string>

namespace geolattice {

void reportSetUpTries(const GLPrintPipeline::SetUpTries& tries, int chosenRank,
                      const std::function<Json&(const char*)>& section) {
  if (!tries.orientations.empty()) {
    Json list = Json::array();
    for (const auto& t : tries.orientations) {
      list.push_back({{"rank", t.rank},
                      {"ok", t.ok},
                      {"colliding_stations", t.colliding},
                      {"stations", t.stations},
                      {"pedestal_mm", t.pedestal},
                      {"seconds", t.seconds}});
    }
    Json& orient = section("orient");
    orient["tries"] = list;
    orient["chosen_rank"] = chosenRank;
  }
  if (tries.pedestals.size() > 1) {
    Json list = Json::array();
    for (const auto& t : tries.pedestals) {
      list.push_back({{"height_mm", t.height},
                      {"ok", t.ok},
                      {"colliding_stations", t.colliding},
                      {"plate_stations", t.plate},
                      {"stations", t.stations},
                      {"seconds", t.seconds}});
    }
    section("orient")["pedestal_tries"] = list;
  }
  if (tries.orders.size() > 1) {
    Json list = Json::array();
    for (const auto& t : tries.orders) {
      list.push_back({{"strategy", std::string(sequenceStrategyName(
                                       static_cast<SequenceStrategy>(t.strategy)))},
                      {"ok", t.ok},
                      {"colliding_stations", t.colliding},
                      {"stations", t.stations},
                      {"seconds", t.seconds}});
    }
    section("sequence")["order_tries"] = list;
  }
}

}  // namespace geolattice
