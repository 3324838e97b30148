#include "results/measurement_settings.h"

namespace raygate {

// Documents name the counted clock in tracer_clock; some older ones only in timing_source.
bool MeasurementSettings::simulated() const {
  return timing_source == TimingSource::simulated || tracer_clock == "simulated-cycles";
}

}  // namespace raygate
