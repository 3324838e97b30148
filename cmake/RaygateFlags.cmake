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

# Sanitized builds (the asan and fuzz presets put -fsanitize=... in CMAKE_CXX_FLAGS).
set(RAYGATE_SANITIZED FALSE)
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=")
  set(RAYGATE_SANITIZED TRUE)
endif()

# raygate_unsanitized(target): build a program without the sanitizers even in a sanitized build.
# Only for programs whose own footprint is what a test measures (a sanitizer's shadow memory
# would be measured with it) or that must link statically (the sanitizer runtimes are shared
# libraries that must be loaded first, so a -static program cannot carry them). The options come
# after CMAKE_CXX_FLAGS and CMAKE_EXE_LINKER_FLAGS on the command lines, so they win.
function(raygate_unsanitized target)
  if(RAYGATE_SANITIZED)
    target_compile_options(${target} PRIVATE -fno-sanitize=all)
    target_link_options(${target} PRIVATE -fno-sanitize=all)
  endif()
endfunction()
