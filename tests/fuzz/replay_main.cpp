// A main() for a libFuzzer harness built without libFuzzer (GCC, the sanitizer build): runs
// every file named on the command line (directories: every file in them) through
// LLVMFuzzerTestOneInput, then --mutate N more inputs made from those by seeded random byte
// changes, so that the sanitizer job replays the seed corpus and a little more on every run.
//   fuzz_replay [--mutate N] [--seed S] PATH...
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  std::vector<std::vector<uint8_t>> inputs;
  long mutate = 0;
  unsigned seed = 18;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--mutate" && i + 1 < argc) {
      mutate = std::atol(argv[++i]);
      continue;
    }
    if (a == "--seed" && i + 1 < argc) {
      seed = static_cast<unsigned>(std::atol(argv[++i]));
      continue;
    }
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(a)) {
      for (const auto& e : std::filesystem::directory_iterator(a))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.emplace_back(a);
    }
    for (const auto& f : files) {
      std::ifstream in(f, std::ios::binary);
      inputs.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "usage: fuzz_replay [--mutate N] [--seed S] PATH...\n");
    return 2;
  }
  for (const auto& in : inputs)
    LLVMFuzzerTestOneInput(in.data(), in.size());
  std::mt19937 rng(seed);
  for (long n = 0; n < mutate; ++n) {
    std::vector<uint8_t> data = inputs[rng() % inputs.size()];
    const int changes = 1 + static_cast<int>(rng() % 16);
    for (int c = 0; c < changes; ++c) {
      const uint32_t kind = rng() % 3;
      if (kind == 0 && !data.empty()) {
        data[rng() % data.size()] = static_cast<uint8_t>(rng());
      } else if (kind == 1) {
        data.insert(data.begin() + static_cast<long>(data.empty() ? 0 : rng() % data.size()),
                    static_cast<uint8_t>(rng()));
      } else if (!data.empty()) {
        data.erase(data.begin() + static_cast<long>(rng() % data.size()));
      }
    }
    LLVMFuzzerTestOneInput(data.data(), data.size());
  }
  std::printf("fuzz_replay: %zu inputs and %ld mutations ran\n", inputs.size(), mutate);
  return 0;
}
