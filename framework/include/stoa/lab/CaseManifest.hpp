#pragma once
// A lab's graded cases, read from its manifest (labs/NN_name/cases.ini).
// Needs no GL context; the grader and the lab apps both read it.
//
//   # comment
//   lab = 01_transforms
//   title = Transforms and cameras
//
//   [case orbit_front]
//   description = The test scene from the orbit camera
//   resolution = 512 384
//   points = 10
//   visibility = visible            # visible | hidden
//   tolerance = 12                  # optional, see CompareOptions
//   max_bad_fraction = 0.002        # optional
//   max_flip_mean = 0.05            # optional
//   camera = orbit                  # any other key is a scene parameter the lab reads
//   target = 0 0.5 0
//
// Keys before the first [case] section describe the lab. Inside a section,
// the keys above are typed here; the others are kept with their line numbers
// and read by the lab through the getters, which throw InputError naming the
// manifest file and the line of the key.

#include <stoa/image/ImageCompare.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace stoa {

enum class Visibility { Visible, Hidden };

class CaseSpec {
public:
    std::string name;                // [case NAME]: letters, digits, '_' and '-'
    std::string description;
    int width = 512;
    int height = 512;
    double points = 1.0;
    Visibility visibility = Visibility::Visible;
    CompareOptions compare;          // defaults unless the case sets tolerance / max_bad_fraction / max_flip_mean
    std::string check;               // `check = NAME`: a property check (PropertyCheck.hpp), no picture; "" otherwise
    std::string file;                // the manifest it came from
    int line = 0;                    // the line of its [case ...] header

    /// Whether the case sets the scene parameter `key`; asking counts as reading it.
    bool has(const std::string& key) const;
    /// Getters for scene parameters. Missing key: the fallback, or InputError when none is given.
    /// A value that does not parse is an InputError even when there is a fallback.
    /// Numbers are read in the "C" locale; a vec3 is three numbers separated by blanks.
    std::string getString(const std::string& key, std::optional<std::string> fallback = std::nullopt) const;
    double getNumber(const std::string& key, std::optional<double> fallback = std::nullopt) const;
    int getInt(const std::string& key, std::optional<int> fallback = std::nullopt) const;
    glm::vec3 getVec3(const std::string& key, std::optional<glm::vec3> fallback = std::nullopt) const;
    /// A number (an integer) from `min` to `max`, both included; the fallback is not checked.
    double getNumberInRange(const std::string& key, double min, double max,
                            std::optional<double> fallback = std::nullopt) const;
    int getIntInRange(const std::string& key, int min, int max, std::optional<int> fallback = std::nullopt) const;
    /// Exactly `count` numbers separated by blanks; `meaning` names them for the error,
    /// e.g. getNumbers("sun", 6, "direction x y z, colour r g b").
    std::vector<float> getNumbers(const std::string& key, std::size_t count, const std::string& meaning) const;
    /// One of `choices` ("single", "2x2", "3x3"); any other value is an error that lists them.
    std::string getChoice(const std::string& key, const std::vector<std::string>& choices,
                          std::optional<std::string> fallback = std::nullopt) const;
    /// "on" or "off".
    bool getSwitch(const std::string& key, bool fallback) const;
    /// For what the getters cannot check alone (two keys that exclude each other, a
    /// value outside a list the lab builds): throws InputError at the line of `key`,
    /// or of the case's header where the case does not set `key`.
    [[noreturn]] void reject(const std::string& key, const std::string& message) const;
    /// Throws InputError naming the first key (in file order) that neither has() nor a
    /// getter has asked for: a typo in the manifest. Call it after reading the case.
    void requireAllKeysUsed() const;

    /// Used by the parser; replaces an earlier value of `key`.
    void setParameter(const std::string& key, const std::string& value, int line);

private:
    struct Parameter {
        std::string value;
        int line = 0;
        mutable bool used = false;
    };
    const Parameter* find(const std::string& key) const;
    [[noreturn]] void fail(const Parameter& parameter, const std::string& key, const std::string& expected) const;
    std::map<std::string, Parameter> m_parameters;
    mutable std::vector<std::string> m_requested;  // keys asked for but absent: "did you mean" candidates
};

struct LabManifest {
    std::string lab;                 // e.g. "01_transforms"
    std::string title;
    std::string file;
    std::vector<CaseSpec> cases;     // in file order

    /// nullptr when there is no such case.
    const CaseSpec* find(const std::string& name) const;
    /// "orbit_front, orbit_side, ..." for error messages.
    std::string caseNames() const;
    /// The cases that render a picture, in file order (not the property checks).
    std::vector<const CaseSpec*> pictureCases() const;
};

/// A key of a case that the manifest parser reads itself (`resolution`,
/// `tolerance`, `check`, ...), as opposed to the lab's scene parameters.
struct CaseKey {
    const char* key;
    const char* expected;   // what a good value looks like, for the error message
    /// Stores a value in the case; false when it does not parse (nothing stored).
    bool (*read)(CaseSpec& spec, const std::string& value);
};

/// Every typed case key, in one table: it drives parsing, errors and "did you mean".
const std::vector<CaseKey>& caseKeys();
/// The table's entry for `key`; nullptr for a scene parameter.
const CaseKey* findCaseKey(const std::string& key);

/// Parses a manifest. Throws InputError with file and line on a syntax error, an
/// unknown lab-level key, a duplicate case or key, or a typed value that does not parse.
LabManifest loadManifest(const std::filesystem::path& path);
/// Parses manifest text; `file` is used in error messages only.
LabManifest parseManifest(const std::string& text, const std::string& file);

} // namespace stoa
