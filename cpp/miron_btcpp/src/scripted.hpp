// A scripted run (miron-btcpp-run --script FILE): no bus, no skill interface. Every action of the
// script returns the next status of its list (past the end the last one again), as the BT.CPP 4
// oracle scenarios of org.miron.executor do; VariantAction reads the decisions the script sets
// before given ticks. One JSON line per tick: root status, leaf executions, blackboard values.
// The same scenario run on the Java executor must give the same lines (tick-by-tick equality).
#pragma once

#include <string>

namespace miron::btcpp
{
/** Runs the scenario file; returns the process exit status. */
int runScripted(const std::string& scenario_file, const std::string& plugin);
}  // namespace miron::btcpp
