// The cost of the data-set checksum (docs/performance.md, "Damaged data
// sets"): zlib's CRC-32 on the bytes of a data-set file in memory, the whole
// check before HDF5 opens a file (h5::verify: read from the page cache plus
// CRC-32), and opening a data set (DatasetReader: the check, then HDF5).
//
// The file: 4 knots of 250 equilibria of n = 400 vertices each (random
// coordinates, which deflate cannot shrink), about 10 MB, written once by
// DatasetWriter to the temporary folder and removed at the end. Bytes per second are the file's size
// divided by the time per iteration.
#include <benchmark/benchmark.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/dataset/h5.hpp"

namespace {

ek::KnotEntry random_entry(const std::string& name, int m, int n, std::mt19937_64& rng) {
  std::normal_distribution<double> coordinate(0.0, 10.0);
  ek::KnotEntry k;
  k.name = name;
  k.crossing_number = 3;
  k.alexander = {1, -1, 1};
  for (int e = 0; e < m; ++e) {
    ek::Points P(n, 3);
    for (Eigen::Index i = 0; i < P.size(); ++i) P.data()[i] = coordinate(rng);
    k.equilibria.push_back(std::move(P));
  }
  k.attribute_names = {"energy"};
  k.attributes = Eigen::MatrixXd::Constant(m, 1, 1.0);
  for (int r = 0; r < m; ++r) {
    ek::RunRecord run;
    run.sample = r;
    run.equilibrium = r;
    run.status = ek::RunStatus::ConvergedStable;
    k.runs.push_back(run);
  }
  k.similarity = Eigen::MatrixXd::Identity(m, m);
  k.linkage = Eigen::MatrixXd::Zero(m - 1, 4);
  k.samples_used = m;
  return k;
}

/// The benchmark file, written on first use.
const std::string& dataset_file() {
  static const std::string path = [] {
    const std::string p = (std::filesystem::temp_directory_path() / "bench_dataset_crc.h5").string();
    std::mt19937_64 rng(1);
    ek::DatasetMetadata meta = ek::dataset_metadata(ek::ExploreOptions{});
    meta.vertices = 400;
    meta.created = "2026-12-01T00:00:00Z";
    ek::DatasetWriter w(p, meta);
    for (const char* name : {"3_1", "4_1", "5_1", "5_2"}) w.add(random_entry(name, 250, 400, rng));
    w.commit();
    return p;
  }();
  return path;
}

void BM_Crc32InMemory(benchmark::State& state) {
  std::ifstream in(dataset_file(), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  for (auto _ : state) {
    uLong crc = ::crc32(0L, Z_NULL, 0);
    crc = ::crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size()));
    benchmark::DoNotOptimize(crc);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(bytes.size()));
  state.counters["file_bytes"] = static_cast<double>(bytes.size());
}
BENCHMARK(BM_Crc32InMemory)->Unit(benchmark::kMillisecond);

void BM_VerifyChecksum(benchmark::State& state) {
  const std::string& path = dataset_file();
  for (auto _ : state) benchmark::DoNotOptimize(ek::h5::verify(path));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(std::filesystem::file_size(path)));
}
BENCHMARK(BM_VerifyChecksum)->Unit(benchmark::kMillisecond);

void BM_OpenDataset(benchmark::State& state) {
  const std::string& path = dataset_file();
  for (auto _ : state) {
    ek::DatasetReader r(path);
    benchmark::DoNotOptimize(r.knot_names().size());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(std::filesystem::file_size(path)));
}
BENCHMARK(BM_OpenDataset)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove(dataset_file());
  return 0;
}
