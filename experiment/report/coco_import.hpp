#pragma once
// A COCO data set read as published runs (`pride import STORE --coco FOLDER --name NAME`): the bbob
// data COCO's logger writes and cocopp reads, the 2009 format included (numbbo/coco-postprocess,
// cocopp/pproc.py DataSet and readalign.py split, read for the format's facts):
//   bbobexp_f<fid>.info  per function and dimension: a header line ("funcId = 6, DIM = 20,
//                        Precision = ..., algId = ..."), comment lines ("% ..."), and a data line
//                        naming a .dat file followed by one "instance:evaluations|final f - f_target"
//                        per run, in the order of the runs' blocks in that file;
//   <name>.dat           per run a block, its header ("% ... Fopt (<f_opt>) ...") then a line at each
//                        of COCO's target triggers: evaluations, f - f_opt, best f - f_opt, ...;
//   <name>.tdat          the same columns at the evaluation triggers (optional, as for cocopp).
// Each run becomes one published run: the evaluations after which best - f_opt first reached each of
// the store's target precisions (the first .dat line within it, as cocopp's detEvals), its final
// precision, and its evaluations (the larger of the last .dat and .tdat lines', cocopp's maxevals).
// A .tgz is not read here (no archive library is a dependency of pride): extract it first, or use
// Python's pride.import_coco, which extracts it with the standard library and records the archive's
// own name and SHA-256.
#include <string>
#include <vector>

#include "experiment/report/published_files.hpp"
#include "experiment/storage/published.hpp"

namespace pride::report {

using CocoImportOptions = PublishedImportOptions;

/// The runs of the COCO bbob data set in `folder` (every .info file under it). InputError, naming
/// the file and line, for a missing file, a malformed line, a suite other than bbob, or a data file
/// whose runs do not match its .info line.
storage::PublishedSet read_coco(const std::string& folder, const CocoImportOptions& options);

/// read_coco's runs added to the store at `store` (created when absent), in one transaction:
/// storage::Writer::import_published, its refusals included. `precisions` and `precisions_json` are
/// the target precisions campaigns record (campaign::coco_precisions()).
storage::ImportSummary import_coco(const std::string& store, const std::string& folder,
                                   const CocoImportOptions& options, const std::vector<double>& precisions,
                                   const std::string& precisions_json);

}  // namespace pride::report
