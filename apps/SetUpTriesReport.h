#pragma once
/// @file SetUpTriesReport.h
/// @brief report.json's record of GLPrintPipeline::FindAPrintableSetUp: the orientations
/// (orient.tries, orient.chosen_rank), pedestal heights (orient.pedestal_tries) and print orders
/// (sequence.order_tries) tried after a colliding toolpath, each with its colliding stations.
#include "GLPrintPipeline.h"

#include <nlohmann/json.hpp>

#include <functional>

namespace geolattice {

using Json = nlohmann::ordered_json;

/// `section(name)` returns report.json's section `name` (made when missing). Only the kinds of
/// tries that ran are written (pedestals and orders: when more than the first ran).
void reportSetUpTries(const GLPrintPipeline::SetUpTries& tries, int chosenRank,
                      const std::function<Json&(const char*)>& section);

}  // namespace geolattice
