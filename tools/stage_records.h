// tools/stage_records.h — OUTDIR/stages.json, `run`'s memory of which stages completed: for each,
// the fingerprint of the inputs it ran with, the files it read and the artefacts it left (size
// and FNV-1a 64, io/file_digest.h). A stage is reused only when its record holds: same inputs, the
// files it read still as their producer recorded them, every artefact present and unchanged.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/file_digest.h"

namespace fluidsound::tools {

/// Files are named relative to OUTDIR, with '/' (e.g. "frames/0003.vdb").
using FileDigests = std::map<std::string, io::FileDigest>;

/// One completed stage.
struct StageRecord {
  std::string inputHash;  ///< fingerprint of the scene, settings and program it ran with
  FileDigests reads;      ///< the files it read, as it found them
  FileDigests artefacts;  ///< the files it wrote, as it left them
};

/// @brief The records of OUTDIR/stages.json for stages run in a fixed order. A later stage may
///        rewrite an earlier one's artefact in place (transfer fills bubbles.json): the earlier
///        artefact then counts as intact when the file is what the later stage wrote from it.
class StageRecords {
 public:
  /// @param order   the stages in the order they run (each name a key of stages.json)
  /// @param ignore  start with no records (`run --fresh`); stages.json is rewritten as stages run
  /// A missing, unreadable or malformed stages.json, or a malformed record, counts as no record.
  StageRecords(std::filesystem::path outdir, std::vector<std::string> order, bool ignore);

  /// @brief Why `stage` must run, or an empty string if it can be reused: it has a record with
  ///        `inputHash` that lists every file of `reads` and `artefacts` (the files the stage
  ///        reads and writes this time; names the record has beyond them are not looked at), each
  ///        file it read is as the stage before it that produced that file recorded it (or, for a
  ///        file no stage produced, as it is now), and each artefact is present and unchanged.
  ///        Call in stage order, after the earlier stages ran or were reused.
  std::string reasonToRun(const std::string& stage, const std::string& inputHash,
                          const std::vector<std::string>& reads,
                          const std::vector<std::string>& artefacts);

  /// The digest of `file` now (cached until the next complete()); none if it is not a readable
  /// file.
  std::optional<io::FileDigest> currentDigest(const std::string& file);

  /// @brief The digest to record for `file` as an input of `stage`, taken before it runs: the
  ///        version the last earlier stage that wrote `file` recorded, when the file is that
  ///        version or one a later stage rewrote from it (transfer reading the bubbles.json it
  ///        filled on a previous run reads simulate's positions and depths; it rewrites only its
  ///        own transfer values); else the file as it is now. None if it is not a readable file.
  std::optional<io::FileDigest> inputDigest(const std::string& stage, const std::string& file);

  /// `file` as `stage`'s record says it left it, if the record lists it.
  std::optional<io::FileDigest> recordedArtefact(const std::string& stage,
                                                 const std::string& file) const;

  /// @brief Drops `stage`'s record and rewrites stages.json, before the stage runs: a stage
  ///        interrupted part-way leaves no record claiming it completed (with `ignore`, the first
  ///        call also drops the records on disk).
  /// @throws io::OutputError if stages.json cannot be written
  void forget(const std::string& stage);

  /// @brief Records `stage` as completed with `inputHash`, `reads` (digests taken before it ran)
  ///        and the digests of `artefacts` as they are now; rewrites stages.json. An artefact
  ///        that is not a regular file now (written through a link to a device, say) cannot be
  ///        checked later, so then nothing is recorded and the stage will run again.
  /// @return whether the stage was recorded
  /// @throws io::OutputError if stages.json cannot be written
  bool complete(const std::string& stage, const std::string& inputHash, FileDigests reads,
                const std::vector<std::string>& artefacts);

 private:
  /// The digests `file`, an artefact of `stage`, may have now: its own, and what each later stage
  /// that read that version and rewrote the file left.
  std::vector<io::FileDigest> acceptedVersions(const std::string& stage,
                                               const std::string& file) const;
  void write();

  std::filesystem::path outdir_;
  std::vector<std::string> order_;
  std::map<std::string, StageRecord> records_;
  std::map<std::string, std::optional<io::FileDigest>> current_;  ///< cleared by complete()
  bool ignoredOnDisk_ = false;  ///< stages.json holds records `ignore` dropped
};

}  // namespace fluidsound::tools
