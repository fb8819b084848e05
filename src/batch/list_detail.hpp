#pragma once
/// Internal to batch/list*.cpp: what the three list readers share.
#include <map>
#include <string>

#include "batch/list.hpp"

namespace freestand::batch::detail {

/// Appends entries to a list, each name checked (check_name) and unique ignoring case.
class EntryCollector {
  public:
    explicit EntryCollector(BatchList& list) : list_(list) {}
    /// name_at locates the entry's name (or what it came from) for an InputError.
    void add(BatchEntry entry, const SourceLocation& name_at);

  private:
    BatchList& list_;
    std::map<std::string, std::string> seen_;  ///< lower-case name -> where it was given
};

/// A case path as a list gives it, resolved against the list file's folder.
std::filesystem::path resolve_case(const std::string& given, const std::string& list_label);

/// Throws InputError at where unless the list has at least one entry.
void require_entries(const BatchList& list, const SourceLocation& where, const std::string& what);

}  // namespace freestand::batch::detail
