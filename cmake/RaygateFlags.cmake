# Compiler flags. Two kinds of code live here:
#  * ordinary code (the harness), built as the preset says (Release, Debug, ASan);
#  * instrument code (the baseline tracer and the SPD generators), whose output must be the same
#    bytes on every machine and in every build type. Those targets get fixed optimisation and no
#    floating-point contraction: FMA fusion changes results in the last bit (spd-spec.md §2.3, §8).

add_library(raygate_warnings INTERFACE)
target_compile_options(raygate_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                       -Wno-sign-conversion)

# raygate_instrument_flags(target): pin the flags of a target whose numbers are part of a measurement.
function(raygate_instrument_flags target)
  # Appended after CMAKE_CXX_FLAGS_<CONFIG>, so this -O2 wins over a Debug build's -O0.
  target_compile_options(${target} PRIVATE -O2 -ffp-contract=off -fno-fast-math)
endfunction()
