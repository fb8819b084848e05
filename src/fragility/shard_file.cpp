#include "fragility/shard_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>

#include "core/file_io.hpp"
#include "core/text_parse.hpp"

namespace freestand::fragility {

namespace fs = std::filesystem;

fs::path write_shard(const fs::path& dir, const std::string& kind, int k, int n,
                     const nlohmann::ordered_json& run,
                     const std::vector<nlohmann::ordered_json>& records) {
    std::string text = nlohmann::ordered_json{{"freestand_shard", 1},
                                              {"kind", kind},
                                              {"shard", k},
                                              {"of", n},
                                              {"run", run}}
                           .dump() +
                       "\n";
    for (const auto& r : records) text += r.dump() + "\n";
    std::error_code ec;
    fs::create_directories(dir, ec);
    const fs::path file = dir / fmt::format("shard-{}-of-{}.jsonl", k, n);
    core::write_file_atomic(file, text);
    return file;
}

namespace shard_file_detail {

/// j[key] as an int; throws when it is not a whole number an int holds (nlohmann's own
/// conversion of 1e39 to int is undefined behaviour, not an exception).
int whole_number(const nlohmann::json& j, const char* key) {
    const nlohmann::json& v = j.at(key);
    constexpr auto int_max = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (v.is_number_unsigned() && v.get<std::uint64_t>() <= int_max) return v.get<int>();
    if (v.is_number_integer() && !v.is_number_unsigned() &&
        v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
        v.get<std::int64_t>() <= std::numeric_limits<int>::max())
        return v.get<int>();
    throw std::runtime_error(key);
}

void read_header(const nlohmann::json& j, ShardFile& s) {
    try {
        if (whole_number(j, "freestand_shard") != 1) throw std::runtime_error("version");
        s.kind = j.at("kind").get<std::string>();
        s.k = whole_number(j, "shard");
        s.n = whole_number(j, "of");
        s.run = j.at("run");
    } catch (const std::exception&) {
        throw InputError(SourceLocation{s.file, 1, "header"},
                         "expected a freestand shard header {\"freestand_shard\": 1, "
                         "\"kind\", \"shard\", \"of\", \"run\"}");
    }
}

std::vector<fs::path> shard_files(const std::vector<fs::path>& paths) {
    std::vector<fs::path> out;
    for (const fs::path& p : paths) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            std::vector<fs::path> here;
            for (const auto& e : fs::directory_iterator(p)) {
                const std::string name = e.path().filename().string();
                if (name.rfind("shard-", 0) == 0 && e.path().extension() == ".jsonl")
                    here.push_back(e.path());
            }
            std::sort(here.begin(), here.end());
            if (here.empty())
                throw InputError(SourceLocation{p.string(), 0, ""},
                                 "no shard-K-of-N.jsonl file in this folder");
            out.insert(out.end(), here.begin(), here.end());
        } else if (fs::exists(p, ec)) {
            out.push_back(p);
        } else {
            throw IoError(fmt::format("{}: no such file or folder", p.string()));
        }
    }
    return out;
}

}  // namespace shard_file_detail

ShardFile parse_shard(const std::string& text, const std::string& file) {
    ShardFile s;
    s.file = file;
    std::istringstream in(std::string(core::text::utf8_text(text, file)));
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        nlohmann::json j;
        try {
            j = nlohmann::json::parse(line);
        } catch (const nlohmann::json::exception& e) {
            throw InputError(SourceLocation{file, number, ""},
                             fmt::format("not a JSON line ({})", e.what()));
        }
        if (number == 1) {
            shard_file_detail::read_header(j, s);
            continue;
        }
        s.records.push_back(std::move(j));
        s.record_lines.push_back(number);
    }
    if (number == 0) throw InputError(SourceLocation{file, 0, ""}, "empty shard file");
    return s;
}

ShardSet join_shards(std::vector<ShardFile> shards) {
    std::map<int, ShardFile> by_index;
    int of = 0;
    for (ShardFile& s : shards) {
        if (!by_index.empty()) {
            const ShardFile& first = by_index.begin()->second;
            if (s.kind != first.kind || s.n != first.n || s.run != first.run)
                throw InputError(
                    SourceLocation{s.file, 1, "run"},
                    fmt::format("this shard belongs to another run than {} (kind, shard count "
                                "or run settings differ)",
                                first.file));
        }
        if (by_index.count(s.k))
            throw InputError(SourceLocation{s.file, 1, "shard"},
                             fmt::format("shard {} of {} is also in {}", s.k, s.n,
                                         by_index.at(s.k).file));
        of = s.n;
        const int k = s.k;
        by_index.emplace(k, std::move(s));
    }
    for (int k = 1; k <= of; ++k)
        if (!by_index.count(k))
            throw InputError(SourceLocation{"", 0, "shards"},
                             fmt::format("shard {} of {} is missing", k, of));
    if (by_index.empty()) throw InputError(SourceLocation{"", 0, "shards"}, "no shard given");
    ShardSet out;
    out.kind = by_index.begin()->second.kind;
    out.run = by_index.begin()->second.run;
    out.run_at = SourceLocation{by_index.begin()->second.file, 1, ""};
    for (auto& [k, s] : by_index) {
        for (std::size_t i = 0; i < s.records.size(); ++i) {
            out.records.push_back(std::move(s.records[i]));
            out.record_at.push_back(SourceLocation{s.file, s.record_lines[i], ""});
        }
    }
    return out;
}

ShardSet read_shards(const std::vector<fs::path>& paths) {
    std::vector<ShardFile> shards;
    for (const fs::path& file : shard_file_detail::shard_files(paths))
        shards.push_back(parse_shard(core::read_text_file(file), file.string()));
    return join_shards(std::move(shards));
}

}  // namespace freestand::fragility
