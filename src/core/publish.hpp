#pragma once
/// Publishing a run's output folder as a whole: a reader of the folder sees all of
/// the previous run's files or all of this run's, never a mix, and two runs into one folder do
/// not interleave.
///
/// Holding an exclusive lock on the parent folder (flock), the files are written into a fresh
/// staging folder beside the target, the target is renamed aside and the staging folder
/// renamed into its place; the old folder is then removed. Between the two renames the folder
/// is briefly absent, never mixed, so a reader that opens the folder once and reads its files
/// through it sees one run. Files in the target that neither this run nor the previous one
/// wrote (a user's note, say) are carried over as hard links. Left-overs of killed runs
/// (staging and renamed-aside folders) are removed by the next publish; one that cannot be
/// removed is named on standard error.
///
/// The path is normalised first ("new/" and "new" are one folder); the root is refused. The
/// working folder (or one holding it, `--out .`) is not renamed aside, which would leave a
/// shell standing in it in a removed folder: its entries are replaced one by one, the marker
/// last, so a reader may briefly see files of both runs there.
///
/// A previous run that cannot be removed (no write access to the folder or a sub-folder) is an
/// IoError before anything moves.
///
/// Only a folder freestand owns is replaced: absent, empty, or marked by the file
/// `.freestand-run` a previous publish left. Anything else is an IoError before anything is
/// written, as are: a target that is a symlink or not a folder, an entry that is neither a
/// regular file nor a sub-folder of this run or the previous one, and a file of the run that
/// would replace an input the process read (core::read_input_file).
///
/// A run may write one level of sub-folders (a batch's component reports): each gets
/// its own `.freestand-run` listing its files, so it reads exactly as a folder published on its
/// own, and the top marker lists it as "name/". A sub-folder is replaced with the folder; files
/// added to it by hand are carried over when the run writes it again, and a sub-folder the run
/// no longer writes is removed, which is refused (IoError) while it holds such files.
#include <filesystem>
#include <string>
#include <vector>

namespace freestand::core {

/// One file of a run's output folder: a plain file name, or "folder/name" for a file of a
/// sub-folder (one level; neither part ".", "..", empty or the marker), and its contents.
struct OutputFile {
    std::string name;
    std::string contents;
};

/// Name of the marker file that makes a folder replaceable by the next run.
inline constexpr const char* run_marker = ".freestand-run";

/// Publishes files as the whole content of dir (see above). Throws IoError naming the path.
void publish_folder(const std::filesystem::path& dir, const std::vector<OutputFile>& files);

/// The checks publish_folder makes of dir itself (not a symlink, a folder, freestand's own),
/// for a long run to refuse its output folder before it starts. publish_folder checks again,
/// with the files, under its lock. Throws IoError naming the path.
void check_publish_target(const std::filesystem::path& dir);

}  // namespace freestand::core
