// One function per SPD scene (spd-spec.md §3); each writes the whole scene through the writer,
// in the SPD's order. `size` has already been validated against the scene's range.
#pragma once

#include "lib/nff_writer.h"

namespace raygate::scenes {

void generate_balls(int size, NffWriter& out);
void generate_gears(int size, NffWriter& out);
void generate_mount(int size, NffWriter& out);
void generate_rings(int size, NffWriter& out);
void generate_teapot(int size, NffWriter& out);
void generate_tetra(int size, NffWriter& out);
void generate_tree(int size, NffWriter& out);
void generate_lattice(int size, NffWriter& out);
void generate_shells(int size, NffWriter& out);
void generate_jacks(int size, NffWriter& out);
void generate_sombrero(int size, NffWriter& out);
void generate_sample(int size, NffWriter& out);
void generate_nurbtst(int size, NffWriter& out);

}  // namespace raygate::scenes
