// SPDX-License-Identifier: MIT
// roiclip::io atomic files: the one writer every roiclip output goes through (GeoJSON, NAME.json,
// overlays, summaries), its one temporary-name scheme, and the one cleaner for temporaries a
// killed process left behind.
//
// A file is written to a hidden temporary ".NAME.tmp.PID.N" in the same folder (so the rename
// cannot cross file systems; PID and a per-process counter N keep concurrent writers apart, the
// leading dot keeps folder listings such as `roiclip run`'s from picking it up), then renamed
// over NAME. A reader never sees a half-written NAME; a crash leaves at most a temporary.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace roiclip::io {

/// Write `bytes` to `file` atomically (temporary file in the same folder, then rename).
/// The folder must exist. On failure no temporary is left and `file` is unchanged.
/// @throws Error naming `file` (never the temporary) and the reason ("is a directory" when `file`
///         is one).
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

/// The temporary name writeFileAtomically() uses for `file` in process `pid` for its `counter`th
/// write: FOLDER/.NAME.tmp.PID.N.
std::filesystem::path temporaryPath(const std::filesystem::path& file, long pid,
                                    unsigned long counter);

/// The PID in a file name made by temporaryPath() (".NAME.tmp.PID.N"), or nothing when the name
/// has another form.
std::optional<long> temporaryOwner(const std::string& filename);

/// Remove the temporaries writeFileAtomically() leaves when a process is killed before its
/// rename: every file under `folder` (recursively; symlinked folders are not followed) whose
/// name has temporaryPath()'s form and whose PID no longer runs. Temporaries of live processes
/// (another writer into the same folder) are left alone. Errors (unreadable folders) are
/// ignored: this only tidies up. @return how many files were removed.
std::size_t removeStaleTemporaries(const std::filesystem::path& folder);

}  // namespace roiclip::io
