#include "SetUpTriesReport.h"

#include "sequence/PrintSequencer.h"

#include <string>

namespace geolattice {

void reportSetUpTries(const GLPrintPipeline::SetUpTries& tries, int chosenRank,
                      const std::function<Json&(const char*)>& section) {
  if (!tries.orientations.empty()) {
    Json list = Json::array();
    for (const auto& t : tries.orientations) {
      Json entry = {{"rank", t.rank},
                    {"ok", t.ok},
                    {"colliding_stations", t.colliding},
                    {"stations", t.stations},
                    {"pedestal_mm", t.pedestal},
                    {"seconds", t.seconds}};
      if (t.robot >= 0) {  // asked: the toolpath was collision-free
        entry["robot_follows"] = t.robot == 1;
        entry["unreachable"] = t.unreachable;
        entry["large_joint_steps"] = t.largeSteps;
        entry["robot_seconds"] = t.robotSeconds;
      }
      list.push_back(entry);
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
