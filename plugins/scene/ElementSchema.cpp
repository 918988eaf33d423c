#include "plugins/scene/ElementSchema.h"

#include <algorithm>
#include <sstream>

namespace milldyn {

std::string SpecError::formatted() const {
    std::ostringstream out;
    out << (m_where.file.empty() ? "<input>" : m_where.file) << ':' << m_where.line << ':'
        << m_where.column << ": error: " << (m_key.empty() ? "<document>" : m_key) << ": "
        << what();
    if (!m_where.includedFrom.empty()) out << " (included from " << m_where.includedFrom << ")";
    std::string line = out.str();
    // One line, always: a reason quoting user text must not break it.
    std::replace(line.begin(), line.end(), '\n', ' ');
    return line;
}

double ElementSpec::number(const std::string& key) const {
    auto it = params.find(key);
    if (it == params.end()) throw error(key, "missing required key");
    return it->second.number;
}

const std::string& ElementSpec::text(const std::string& key) const {
    auto it = params.find(key);
    if (it == params.end()) throw error(key, "missing required key");
    return it->second.text;
}

const std::vector<std::string>& ElementSpec::names(const std::string& key) const {
    auto it = params.find(key);
    if (it == params.end()) throw error(key, "missing required key");
    return it->second.names;
}

const std::vector<double>& ElementSpec::numbers(const std::string& key) const {
    auto it = params.find(key);
    if (it == params.end()) throw error(key, "missing required key");
    return it->second.numbers;
}

bool ElementSpec::has(const std::string& key) const {
    auto it = params.find(key);
    return it != params.end() && it->second.given;
}

SourceLocation ElementSpec::whereOf(const std::string& key) const {
    auto it = params.find(key);
    if (it == params.end() || !it->second.given) return where;
    return it->second.where;
}

SpecError ElementSpec::error(const std::string& key, const std::string& reason) const {
    const std::string qualified = name.empty() ? key : name + "." + key;
    return SpecError(whereOf(key), qualified, reason);
}

const ParamSchema* ElementSchema::find(const std::string& key) const {
    for (const auto& p : params)
        if (p.key == key) return &p;
    return nullptr;
}

ParamSchema ParamSchema::quantity(std::string key, std::string unit, std::string doc) {
    ParamSchema p;
    p.key = std::move(key);
    p.kind = ParamKind::Quantity;
    p.unit = std::move(unit);
    p.doc = std::move(doc);
    return p;
}

ParamSchema ParamSchema::choice(std::string key, std::vector<std::string> choices, std::string doc) {
    ParamSchema p;
    p.key = std::move(key);
    p.kind = ParamKind::Choice;
    p.choices = std::move(choices);
    p.doc = std::move(doc);
    return p;
}

ParamSchema ParamSchema::bodyList(std::string key, std::size_t minCount, std::size_t maxCount, std::string doc) {
    ParamSchema p = body(std::move(key), std::move(doc));
    p.kind = ParamKind::BodyList;
    p.minCount = minCount;
    p.maxCount = maxCount;
    return p;
}

ParamSchema ParamSchema::quantityList(std::string key, std::string unit, std::size_t minCount, std::size_t maxCount,
                                      std::string doc) {
    ParamSchema p = quantity(std::move(key), std::move(unit), std::move(doc));
    p.kind = ParamKind::QuantityList;
    p.minCount = minCount;
    p.maxCount = maxCount;
    return p;
}

ParamSchema ParamSchema::body(std::string key, std::string doc) {
    ParamSchema p;
    p.key = std::move(key);
    p.kind = ParamKind::BodyRef;
    p.doc = std::move(doc);
    return p;
}

ParamSchema ParamSchema::bodyPair(std::string key, std::string doc) {
    ParamSchema p = body(std::move(key), std::move(doc));
    p.kind = ParamKind::BodyPair;
    return p;
}

ParamSchema ParamSchema::text(std::string key, std::string doc) {
    ParamSchema p = body(std::move(key), std::move(doc));
    p.kind = ParamKind::Text;
    return p;
}

ParamSchema& ParamSchema::optional(double defaultSI) {
    required = false;
    defaultValue = defaultSI;
    return *this;
}

ParamSchema& ParamSchema::optional(std::string defaultWord) {
    required = false;
    defaultText = std::move(defaultWord);
    return *this;
}

ParamSchema& ParamSchema::above(double bound) {
    min = bound;
    minExclusive = true;
    return *this;
}

ParamSchema& ParamSchema::atLeast(double bound) {
    min = bound;
    minExclusive = false;
    return *this;
}

ParamSchema& ParamSchema::below(double bound) {
    max = bound;
    maxExclusive = true;
    return *this;
}

ParamSchema& ParamSchema::atMost(double bound) {
    max = bound;
    maxExclusive = false;
    return *this;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            const std::size_t cost = (a[i - 1] == b[j - 1]) ? 0 : 1;
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + cost});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string nearestName(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = std::string::npos;
    for (const auto& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    // A suggestion that needs more edits than a third of the word is noise.
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    return bestDistance <= limit ? best : std::string();
}

}  // namespace milldyn
