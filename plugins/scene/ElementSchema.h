#pragma once
// Plain data shared by the model-file reader and the element registry.
// Nothing here knows Simbody or YAML: an element type declares which keys it
// accepts (with SI unit and valid range), the reader checks a model file
// against that declaration, and the element's builder receives the checked
// values as an ElementSpec.

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace milldyn {

/// Where a value came from, for diagnostics ("file:line:col"). 1-based.
struct SourceLocation {
    SourceLocation() = default;
    SourceLocation(std::string file_, int line_, int column_, std::string includedFrom_ = {})
        : file(std::move(file_)), line(line_), column(column_), includedFrom(std::move(includedFrom_)) {}
    std::string file;
    int line = 0;
    int column = 0;
    /// For a value from an included part file: the include chain,
    /// "a.yaml:4:5" or "b.yaml:2:3, included from a.yaml:4:5" (else empty).
    std::string includedFrom;
};

/// Thrown for bad input; carries the location and the key so the driver can
/// print `file:line:col: error: key: reason` and exit 2.
class SpecError : public std::runtime_error {
public:
    SpecError(SourceLocation where, std::string key, const std::string& reason)
        : std::runtime_error(reason), m_where(std::move(where)), m_key(std::move(key)) {}
    const SourceLocation& where() const { return m_where; }
    const std::string& key() const { return m_key; }
    /// The one-line diagnostic the driver prints.
    std::string formatted() const;

private:
    SourceLocation m_where;
    std::string m_key;
};

enum class ParamKind {
    Quantity,   ///< a number with an optional unit, converted to SI
    Choice,     ///< one word out of a fixed list
    BodyRef,    ///< the name of a body in the model
    BodyPair,   ///< a list of two body names [from, to]
    BodyList,   ///< a list of body names (minCount..maxCount)
    QuantityList,  ///< a list of numbers with units, all in `unit`
    Text,       ///< free text (names, descriptions)
};

/// One key an element type accepts.
struct ParamSchema {
    std::string key;
    ParamKind kind = ParamKind::Quantity;
    std::string unit = "1";             ///< SI unit for Quantity ("N*m/rad", "1")
    bool required = true;
    std::optional<double> defaultValue; ///< Quantity default (SI), if optional
    std::string defaultText;            ///< Choice/Text default, if optional
    std::vector<std::string> choices;   ///< Choice: allowed words
    std::optional<double> min;          ///< Quantity lower bound
    bool minExclusive = false;
    std::optional<double> max;          ///< Quantity upper bound
    bool maxExclusive = false;
    std::size_t minCount = 0;           ///< lists: fewest items
    std::size_t maxCount = 1000;        ///< lists: most items
    std::string doc;                    ///< one line for docs and `info`

    // Readable declarations: quantity("stiffness", "N*m/rad", "...").atLeast(0)
    static ParamSchema quantity(std::string key, std::string unit, std::string doc);
    static ParamSchema choice(std::string key, std::vector<std::string> choices, std::string doc);
    static ParamSchema body(std::string key, std::string doc);
    static ParamSchema bodyPair(std::string key, std::string doc);
    static ParamSchema text(std::string key, std::string doc);
    static ParamSchema bodyList(std::string key, std::size_t minCount, std::size_t maxCount, std::string doc);
    static ParamSchema quantityList(std::string key, std::string unit, std::size_t minCount, std::size_t maxCount,
                                    std::string doc);
    ParamSchema& optional(double defaultSI);
    ParamSchema& optional(std::string defaultWord);
    ParamSchema& above(double bound);    ///< value > bound
    ParamSchema& atLeast(double bound);  ///< value >= bound
    ParamSchema& below(double bound);    ///< value < bound
    ParamSchema& atMost(double bound);   ///< value <= bound
};

/// A checked parameter value.
struct ParamValue {
    double number = 0;                  ///< Quantity, SI
    std::string text;                   ///< Choice, BodyRef, Text
    std::vector<std::string> names;     ///< BodyPair, BodyList
    std::vector<SourceLocation> itemWhere;  ///< where each list item was written
    std::vector<double> numbers;        ///< QuantityList, SI
    SourceLocation where;
    bool given = false;                 ///< false: filled from the default
};

/// One element instance as read from a model file.
struct ElementSpec {
    std::string type;
    std::string name;
    SourceLocation where;
    std::map<std::string, ParamValue> params;
    /// Fidelity levels this element belongs to (empty: all).
    std::vector<std::string> fidelity;

    /// Quantity in SI; throws SpecError if absent.
    double number(const std::string& key) const;
    const std::string& text(const std::string& key) const;
    const std::vector<std::string>& names(const std::string& key) const;
    const std::vector<double>& numbers(const std::string& key) const;
    bool has(const std::string& key) const;
    /// The location of a key (the element's own if the key was defaulted).
    SourceLocation whereOf(const std::string& key) const;
    /// A SpecError about this key, located where the key was written.
    SpecError error(const std::string& key, const std::string& reason) const;
};

/// The declaration of an element type: its keys and a check across keys
/// (for example rated speed below synchronous speed). The cross-check
/// throws SpecError via ElementSpec::error().
struct ElementSchema {
    std::string type;
    std::string doc;
    std::vector<ParamSchema> params;
    std::function<void(const ElementSpec&)> crossCheck;
    /// Output only (JointReaction): it changes nothing in the motion, so a
    /// model whose `outputs.columns` names none of its outputs skips it.
    bool outputOnly = false;
    /// Loaded by weight (a charge, a journal): a model without `gravity:`
    /// gets a warning naming it (issue 20 item 8).
    bool needsGravity = false;

    // Capabilities generic code asks for instead of type names (issue 31
    // item 4; docs/architecture.md "Element capabilities"). Empty: none.

    /// A setting that ties the element to certain analyses: with key `key`
    /// at text `value`, the element is
    ///   EachInstant: a condition of each instant, solved per configuration
    ///                (a held charge's wall torque): kinetostatic, or a
    ///                transient replayed sample by sample;
    ///   StepHistory: a history carried from step to step (a frozen
    ///                charge's release latch): an integrated transient only.
    struct AnalysisNeed {
        enum class Kind { EachInstant, StepHistory };
        std::string key, value;
        Kind kind = Kind::EachInstant;
        std::string why;          ///< "a held charge's wall torque is solved at each instant"
        std::string alternative;  ///< what to give instead: "motion: with_drum or dynamic_lag"
        bool matches(const ElementSpec& e) const { return e.has(key) && e.text(key) == value; }
    };
    std::vector<AnalysisNeed> analysisNeeds;
    /// Keys that set the state at t = 0, with what they set ("the drum's
    /// speed"): only a transient with `initial_state: file` keeps them, so
    /// any other analysis refuses one given.
    std::vector<std::pair<std::string, std::string>> initialStateKeys;
    /// Key of a speed [rad/s] below which the element's law is regularised
    /// (a dry load's tanh smoothing at standstill): a run-out watched below
    /// a few times it measures the regularisation, not the law.
    std::string regularisationSpeedKey;
    /// Key of a constant resistance torque [N*m] an identification may
    /// adjust (coastdown_identify's `resistance`).
    std::string adjustableResistanceKey;

    const ParamSchema* find(const std::string& key) const;
};

/// Edit distance, for "did you mean" suggestions.
std::size_t editDistance(const std::string& a, const std::string& b);
/// The candidate closest to `word`, or "" if none is close enough to help.
std::string nearestName(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace milldyn
