// Writes the fuzz targets' seed corpus into the folder given as the argument
// (genmesh_fuzz::write_seed_corpus; scripts/fuzz.sh runs it).
#include "genmesh_fuzz.h"

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: fuzz_seeds DIR\n";
    return 2;
  }
  genmesh_fuzz::write_seed_corpus(argv[1]);
  return 0;
}
