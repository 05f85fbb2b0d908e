/// @file
/// Comparing rendered figures with the ones committed in docs/figures, and checking that every
/// image a README shows is a file of the repository.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tri::figures {

/// Compares every file in `rendered` with the file of the same name in `committed`: PNG images
/// pixel for pixel (decoded, so a different encoder setting is not a difference), every other
/// file byte for byte. Returns one message per figure that is missing or differs, naming it and
/// saying where it first differs; empty when all match.
std::vector<std::string> compare_figures(const std::filesystem::path& rendered,
                                         const std::filesystem::path& committed);

/// The files in `committed` that no folder of `rendered_folders` has, except those named in
/// `snapshots` (figures from a timed run, committed by hand). One message per stale file.
std::vector<std::string> stale_figures(const std::filesystem::path& committed,
                                       const std::vector<std::filesystem::path>& rendered_folders,
                                       const std::vector<std::string>& snapshots);

/// Every Markdown image `![alt](path)` in the given files whose path is not an existing file of
/// the repository (resolved relative to the Markdown file, and inside `repository_root`). Links
/// to http(s) addresses count as missing too: the README must read complete offline.
std::vector<std::string> missing_images(const std::filesystem::path& repository_root,
                                        const std::vector<std::filesystem::path>& markdown_files);

}  // namespace tri::figures
