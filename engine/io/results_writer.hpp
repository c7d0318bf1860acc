// Writes results.h5 (docs/results.md). The file is written under "<path>.partial" and renamed to
// <path> only by finish(), so an interrupted run never leaves a file that looks complete.
#pragma once
#include <memory>
#include <string>

#include "engine/io/results.hpp"

namespace dmi {

class ResultsWriter {
 public:
  ResultsWriter(const std::string& path, const RunInfo& info);  // throws std::runtime_error on I/O failure
  // A restarted run: reopens <path>.partial, keeps its first `snapshots` snapshots (those written before the
  // checkpoint), drops any later ones and the histories, and goes on from there. Throws std::runtime_error when the
  // partial file is missing, unreadable, complete, or has fewer snapshots.
  struct Resume {
    std::size_t snapshots = 0;
  };
  ResultsWriter(const std::string& path, const RunInfo& info, Resume resume);
  ~ResultsWriter();  // without finish(): closes the partial file and leaves it under its .partial name
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  void write_snapshot(const Snapshot& s);  // /snapshots/<index> as the run goes
  // Histories, run info numbers/strings (updated), then complete=1, close, rename.
  void finish(const std::vector<double>& time, const std::vector<Series>& series, const RunInfo& info);
  // An interrupted run: the histories so far and the run info go into the .partial file, which keeps complete = 0
  // and its .partial name (an older complete <path> is left as it was).
  void abandon(const std::vector<double>& time, const std::vector<Series>& series, const RunInfo& info);

 private:
  void close_file(const std::vector<double>& time, const std::vector<Series>& series, const RunInfo& info, bool complete);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Reads results.h5; throws std::runtime_error naming the file and what is wrong (missing,
// truncated, not a damimpact file, unsupported version, missing dataset).
Results read_results(const std::string& path, bool with_snapshots = true);

}  // namespace dmi
