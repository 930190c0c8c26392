#pragma once
// HDF5 files edited by Debian's h5py, independent of gesmi's writer: each edit is a few
// lines of Python where `f` is the open file (h5py.File, 'r+') and `np` is numpy. All
// the edits of one call run in one Python process (its start-up costs a tenth of a
// second).

#include <string>
#include <vector>

namespace gesmi::test {

/// Copies of `source`, one per edit, each edited by its lines, in a new temporary folder.
/// A failing edit fails the calling test (its copy is then as far as the edit went).
std::vector<std::string> h5py_edited_copies(const std::string& source, const std::vector<std::string>& edits);

/// One edited copy.
std::string h5py_edited_copy(const std::string& source, const std::string& edit);

}  // namespace gesmi::test
