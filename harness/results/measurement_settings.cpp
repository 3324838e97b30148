#include "results/measurement_settings.h"

namespace raygate {

// Documents name the simulated clock in tracer_clock; some older ones only in timing_source.
bool MeasurementSettings::simulated() const {
  return timing_source == TimingSource::simulated || tracer_clock == "simulated-cycles";
}

std::string MeasurementSettings::measure_unit() const {
  if (unit) return *unit;
  return simulated() ? "cycles" : "seconds";
}

}  // namespace raygate
