// Scene-file parser: directives, their arguments and parameter lists, Include and Import.

#include "core/parser/parser.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/parser/tokenizer.h"

namespace kiln {

namespace {

// A token and the tokenizer (file) it came from.
struct Tok {
    Token t;
    const Tokenizer* src = nullptr;
    FileLoc Loc() const { return src->Loc(t); }
};

// The key under which a file counts as "being parsed", for Include/Import cycle detection.
std::string FileKey(const std::string& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
}

// Files open at once through Include and Import: deeper nesting is an error (a chain of
// includes would otherwise recurse until the stack overflows)
constexpr size_t kMaxIncludeDepth = 128;

bool LooksNumeric(std::string_view w) {
    if (w.empty()) return false;
    char c = w[0];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

// SceneParser
class SceneParser {
  public:
    SceneParser(ParserTarget& target, Diagnostics& diag, std::string searchDirectory,
                uint64_t maxFileBytes = DefaultMaxInputBytes())
        : target(target),
          diag(diag),
          searchDirectory(std::move(searchDirectory)),
          maxFileBytes(maxFileBytes) {}
    // The files Include and Import read, in order
    const std::vector<std::string>& FilesRead() const { return filesRead; }

    // Parses `contents` (and whatever it includes) to the end; `key` identifies the file.
    void Run(std::string contents, std::string filename, std::string key) {
        Push(std::move(contents), std::move(filename), std::move(key));
        ParseDirectives();
    }

  private:
    struct Source {
        std::unique_ptr<Tokenizer> tokenizer;
        std::string key;
    };

    [[noreturn]] static void Fail(const Tok& t, std::string message) {
        throw SceneError(t.Loc(), std::move(message), t.t.raw);
    }

    void Push(std::string contents, std::string filename, std::string key) {
        auto tokenizer = std::make_unique<Tokenizer>(std::move(contents), std::move(filename));
        ++openFiles[key];
        stack.push_back({std::move(tokenizer), std::move(key)});
    }

    // Tokens
    // The next token of the innermost open file, continuing in the including file when an
    // included one ends; nullopt when the outermost file of this run ends.
    std::optional<Tok> Next() {
        if (pending) {
            std::optional<Tok> t = std::move(pending);
            pending.reset();
            return t;
        }
        while (!stack.empty()) {
            Tokenizer* tokenizer = stack.back().tokenizer.get();
            if (std::optional<Token> t = tokenizer->Next()) return Tok{*t, tokenizer};
            eofLoc = tokenizer->EndLoc();
            // Keep the tokenizer (its text backs tokens still in use) until the directive ends.
            finished.push_back(std::move(stack.back().tokenizer));
            if (--openFiles[stack.back().key] == 0) openFiles.erase(stack.back().key);
            stack.pop_back();
        }
        return std::nullopt;
    }
    void Unget(Tok t) { pending = std::move(t); }

    Tok Required(const Tok& directive) {
        std::optional<Tok> t = Next();
        if (!t)
            throw SceneError(eofLoc, "unexpected end of file in the arguments of " +
                                         std::string(directive.t.text) + " (at " +
                                         directive.Loc().ToString() + ")");
        return *t;
    }

    Float NumberArg(const Tok& directive) {
        Tok t = Required(directive);
        Float v;
        if (t.t.kind != TokenKind::Word || !ParseFloat(t.t.text, &v))
            Fail(t, "expected a number as argument of " + std::string(directive.t.text));
        return v;
    }

    std::string StringArg(const Tok& directive, std::string_view what) {
        Tok t = Required(directive);
        if (t.t.kind != TokenKind::String)
            Fail(t, std::string(directive.t.text) + " expects a quoted string (" +
                        std::string(what) + ")");
        return std::string(t.t.text);
    }

    void ExpectBracket(const Tok& directive, TokenKind kind) {
        Tok t = Required(directive);
        if (t.t.kind != kind)
            Fail(t, std::string("expected '") + (kind == TokenKind::OpenBracket ? "[" : "]") +
                        "' in " + std::string(directive.t.text));
    }

    // Parameter lists
    ParsedParameterVector Parameters(const Tok& directive) {
        ParsedParameterVector params;
        while (std::optional<Tok> t = Next()) {
            if (t->t.kind != TokenKind::String) {
                Unget(std::move(*t));
                break;
            }
            params.push_back(Parameter(directive, *t));
            const ParsedParameter& p = params.back();
            for (size_t i = 0; i + 1 < params.size(); ++i)
                if (params[i].name == p.name && params[i].type == p.type) {
                    diag.Warn(p.loc, "parameter '" + p.name +
                                         "' given more than once; the last one is used");
                    break;
                }
        }
        return params;
    }

    ParsedParameter Parameter(const Tok& directive, const Tok& decl) {
        // Declaration: "type name"
        std::string_view text = decl.t.text;
        std::vector<std::string_view> words;
        size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
            size_t start = i;
            while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
            if (i > start) words.push_back(text.substr(start, i - start));
        }
        if (words.size() < 2) Fail(decl, "parameter declaration must be \"type name\"");
        std::string_view type = CanonicalParameterType(words[0]);
        if (type.empty()) Fail(decl, "unknown parameter type '" + std::string(words[0]) + "'");

        ParsedParameter p;
        p.type = std::string(type);
        p.name = std::string(words[1]);
        p.loc = decl.Loc();
        p.searchDirectory = searchDirectory;
        if (words.size() > 2)
            diag.Warn(p.loc,
                      "extra words in parameter declaration \"" + std::string(text) + "\" ignored");

        // Values: one value, or a bracketed list
        ParameterValueKind kind = ValueKindOf(type);
        Tok t = Required(directive);
        if (t.t.kind == TokenKind::OpenBracket) {
            Tok open = t;
            while (true) {
                std::optional<Tok> v = Next();
                if (!v) Fail(open, "unbalanced '[': no matching ']' before the end of file");
                if (v->t.kind == TokenKind::CloseBracket) break;
                if (v->t.kind == TokenKind::OpenBracket) Fail(*v, "unexpected '[' in a list");
                AddValue(p, kind, *v);
            }
        } else if (t.t.kind == TokenKind::CloseBracket) {
            Fail(t, "unexpected ']' (no matching '[')");
        } else {
            AddValue(p, kind, t);
        }

        // Counts
        int perItem = ValuesPerItem(type);
        if (perItem > 1 && p.floats.size() % perItem != 0) {
            if (type == "spectrum")
                Fail(decl, "odd number of values (" + std::to_string(p.floats.size()) +
                               ") for spectrum wavelength/value pairs");
            Fail(decl, std::string(type) + " parameter '" + p.name + "' has " +
                           std::to_string(p.floats.size()) + " values, not a multiple of " +
                           std::to_string(perItem));
        }
        return p;
    }

    void AddValue(ParsedParameter& p, ParameterValueKind kind, const Tok& v) {
        const Token& t = v.t;
        bool isString = t.kind == TokenKind::String;
        switch (kind) {
            case ParameterValueKind::Float: {
                Float f;
                if (isString || !ParseFloat(t.text, &f))
                    Fail(v, "expected a number for " + p.type + " parameter '" + p.name + "'");
                p.floats.push_back(f);
                return;
            }
            case ParameterValueKind::Int: {
                int n;
                if (!isString && ParseInt(t.text, &n)) {
                    p.ints.push_back(n);
                    return;
                }
                Float f;
                if (isString || !ParseFloat(t.text, &f))
                    Fail(v, "expected an integer for parameter '" + p.name + "'");
                // pbrt-v4 accepts a floating-point value, rounding it toward zero.
                if (f != std::trunc(f))
                    diag.Warn(v.Loc(), "floating-point value " + std::string(t.text) +
                                           " will be rounded to an integer");
                constexpr double lo = std::numeric_limits<int>::lowest();
                constexpr double hi = std::numeric_limits<int>::max();
                p.ints.push_back(int(std::clamp(double(f), lo, hi)));
                return;
            }
            case ParameterValueKind::Bool:
                if (t.text == "true" || t.text == "false") {
                    p.bools.push_back(t.text == "true");
                    return;
                }
                Fail(v, "expected true or false for bool parameter '" + p.name + "'");
            case ParameterValueKind::String:
                if (!isString)
                    Fail(v,
                         "expected a quoted string for " + p.type + " parameter '" + p.name + "'");
                p.strings.emplace_back(t.text);
                return;
            case ParameterValueKind::FloatOrString: {
                if (isString) {
                    if (!p.floats.empty())
                        Fail(v, "spectrum parameter '" + p.name + "' mixes numbers and strings");
                    p.strings.emplace_back(t.text);
                    return;
                }
                Float f;
                if (!ParseFloat(t.text, &f))
                    Fail(v, "expected a number or a quoted string for spectrum parameter '" +
                                p.name + "'");
                if (!p.strings.empty())
                    Fail(v, "spectrum parameter '" + p.name + "' mixes numbers and strings");
                p.floats.push_back(f);
                return;
            }
        }
    }

    // Include and Import
    // Opens `name` (resolved against the search directory) for an Include/Import at `t`.
    std::pair<std::string, std::string> OpenFile(const Tok& t, const std::string& name,
                                                 std::string* key) {
        std::string path = ResolveFilename(searchDirectory, name);
        *key = FileKey(path);
        if (openFiles.count(*key)) Fail(t, "'" + name + "' includes itself (directly or not)");
        size_t depth = 0;
        for (const auto& [k, n] : openFiles) depth += size_t(n);
        if (depth >= kMaxIncludeDepth)
            Fail(t, "Include/Import nested more than " + std::to_string(kMaxIncludeDepth) +
                        " files deep");
        std::string contents, error;
        if (!ReadFileContents(path, &contents, &error, maxFileBytes))
            Fail(t, "cannot open '" + path + "': " + error);
        filesRead.push_back(path);
        target.FileContents(contents.size(), t.Loc());
        return {std::move(contents), path};
    }

    void Include(const Tok& directive) {
        Tok f = Required(directive);
        if (f.t.kind != TokenKind::String) Fail(f, "Include expects a quoted filename");
        std::string key;
        auto [contents, path] = OpenFile(f, std::string(f.t.text), &key);
        Push(std::move(contents), std::move(path), std::move(key));
    }

    void Import(const Tok& directive) {
        FileLoc loc = directive.Loc();
        if (!worldBegun) Fail(directive, "Import is only allowed after WorldBegin (use Include)");
        Tok f = Required(directive);
        if (f.t.kind != TokenKind::String) Fail(f, "Import expects a quoted filename");
        std::string key;
        auto [contents, path] = OpenFile(f, std::string(f.t.text), &key);

        // Parse the file on its own, in an attribute block.
        std::vector<Source> saved = std::move(stack);
        stack.clear();
        target.AttributeBegin(loc);
        Run(std::move(contents), std::move(path), std::move(key));
        target.AttributeEnd(loc);
        stack = std::move(saved);
    }

    // Directives
    void ParseDirectives() {
        while (true) {
            finished.clear();  // No token of theirs is held between directives.
            std::optional<Tok> next = Next();
            if (!next) return;
            Directive(*next);
        }
    }

    void Directive(const Tok& d) {
        const Token& t = d.t;
        if (t.kind == TokenKind::String)
            Fail(d, "unexpected string: a parameter list must follow a directive");
        if (t.kind != TokenKind::Word)
            Fail(d, std::string("unexpected '") + std::string(t.text) + "'");
        std::string_view w = t.text;
        FileLoc loc = d.Loc();
        auto named = [&](auto method) {
            std::string name = StringArg(d, "name");
            (target.*method)(name, Parameters(d), loc);
        };

        // Transformations
        if (w == "Identity") {
            target.Identity(loc);
        } else if (w == "Translate" || w == "Scale") {
            Float x = NumberArg(d), y = NumberArg(d), z = NumberArg(d);
            if (w == "Translate")
                target.Translate(x, y, z, loc);
            else
                target.Scale(x, y, z, loc);
        } else if (w == "Rotate") {
            std::array<Float, 4> v;
            for (Float& f : v) f = NumberArg(d);
            target.Rotate(v[0], v[1], v[2], v[3], loc);
        } else if (w == "LookAt") {
            std::array<Float, 9> v;
            for (Float& f : v) f = NumberArg(d);
            target.LookAt(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], loc);
        } else if (w == "Transform" || w == "ConcatTransform") {
            ExpectBracket(d, TokenKind::OpenBracket);
            std::array<Float, 16> m;
            for (Float& f : m) {
                Tok v = Required(d);
                if (v.t.kind == TokenKind::CloseBracket)
                    Fail(v, std::string(w) + " needs 16 numbers");
                if (v.t.kind != TokenKind::Word || !ParseFloat(v.t.text, &f))
                    Fail(v, "expected a number in " + std::string(w));
            }
            ExpectBracket(d, TokenKind::CloseBracket);
            if (w == "Transform")
                target.Transform(m, loc);
            else
                target.ConcatTransform(m, loc);
        } else if (w == "CoordinateSystem") {
            target.CoordinateSystem(StringArg(d, "name"), loc);
        } else if (w == "CoordSysTransform") {
            target.CoordSysTransform(StringArg(d, "name"), loc);
        } else if (w == "ActiveTransform") {
            Tok a = Required(d);
            if (a.t.IsWord("All"))
                target.ActiveTransformAll(loc);
            else if (a.t.IsWord("StartTime"))
                target.ActiveTransformStartTime(loc);
            else if (a.t.IsWord("EndTime"))
                target.ActiveTransformEndTime(loc);
            else
                Fail(a, "ActiveTransform expects All, StartTime or EndTime");
        } else if (w == "TransformTimes") {
            Float start = NumberArg(d), end = NumberArg(d);
            target.TransformTimes(start, end, loc);
        } else if (w == "ReverseOrientation") {
            target.ReverseOrientation(loc);

            // Rendering options
        } else if (w == "Option") {
            std::string name = StringArg(d, "\"type name\"");
            Tok v = Required(d);
            if (v.t.kind == TokenKind::OpenBracket) {
                v = Required(d);
                ExpectBracket(d, TokenKind::CloseBracket);
            }
            if (v.t.kind != TokenKind::Word && v.t.kind != TokenKind::String)
                Fail(v, "expected a value for Option");
            target.Option(name, std::string(v.t.raw), loc);
        } else if (w == "ColorSpace") {
            target.ColorSpace(StringArg(d, "name"), loc);
        } else if (w == "Camera") {
            named(&ParserTarget::Camera);
        } else if (w == "Film") {
            named(&ParserTarget::Film);
        } else if (w == "Sampler") {
            named(&ParserTarget::Sampler);
        } else if (w == "Integrator") {
            named(&ParserTarget::Integrator);
        } else if (w == "PixelFilter") {
            named(&ParserTarget::PixelFilter);
        } else if (w == "Accelerator") {
            named(&ParserTarget::Accelerator);
        } else if (w == "MakeNamedMedium") {
            named(&ParserTarget::MakeNamedMedium);
        } else if (w == "MediumInterface") {
            std::string inside = StringArg(d, "medium name"), outside = inside;
            if (std::optional<Tok> second = Next()) {
                if (second->t.kind == TokenKind::String)
                    outside = std::string(second->t.text);
                else
                    Unget(std::move(*second));
            }
            target.MediumInterface(inside, outside, loc);
        } else if (w == "WorldBegin") {
            worldBegun = true;
            target.WorldBegin(loc);

            // Scene description
        } else if (w == "AttributeBegin") {
            target.AttributeBegin(loc);
        } else if (w == "AttributeEnd") {
            target.AttributeEnd(loc);
        } else if (w == "Attribute") {
            named(&ParserTarget::Attribute);
        } else if (w == "TransformBegin" || w == "TransformEnd") {
            bool begin = w == "TransformBegin";
            bool& warned = begin ? warnedTransformBegin : warnedTransformEnd;
            if (!warned)
                diag.Warn(loc, std::string(w) + " is deprecated; use " +
                                   (begin ? "AttributeBegin" : "AttributeEnd"));
            warned = true;
            if (begin)
                target.AttributeBegin(loc);
            else
                target.AttributeEnd(loc);
        } else if (w == "Shape") {
            named(&ParserTarget::Shape);
        } else if (w == "Texture") {
            std::string name = StringArg(d, "texture name");
            std::string type = StringArg(d, "\"float\" or \"spectrum\"");
            std::string texClass = StringArg(d, "texture class");
            target.Texture(name, type, texClass, Parameters(d), loc);
        } else if (w == "Material") {
            named(&ParserTarget::Material);
        } else if (w == "MakeNamedMaterial") {
            named(&ParserTarget::MakeNamedMaterial);
        } else if (w == "NamedMaterial") {
            target.NamedMaterial(StringArg(d, "material name"), loc);
        } else if (w == "LightSource") {
            named(&ParserTarget::LightSource);
        } else if (w == "AreaLightSource") {
            named(&ParserTarget::AreaLightSource);
        } else if (w == "ObjectBegin") {
            target.ObjectBegin(StringArg(d, "object name"), loc);
        } else if (w == "ObjectEnd") {
            target.ObjectEnd(loc);
        } else if (w == "ObjectInstance") {
            target.ObjectInstance(StringArg(d, "object name"), loc);
        } else if (w == "Include") {
            Include(d);
        } else if (w == "Import") {
            Import(d);
        } else if (w == "WorldEnd") {
            diag.Warn(loc, "WorldEnd is a pbrt-v3 directive; ignored");
        } else if (LooksNumeric(w)) {
            Fail(d, "unexpected value: values must follow a \"type name\" parameter declaration");
        } else {
            Fail(d, "unknown directive");
        }
    }

    ParserTarget& target;
    Diagnostics& diag;
    std::string searchDirectory;
    std::vector<Source> stack;                         // Open files, innermost last.
    std::vector<std::unique_ptr<Tokenizer>> finished;  // Ended during the current directive.
    // Every open file (those of `stack` and those an Import set aside) by key, with a count
    std::unordered_map<std::string, int> openFiles;
    std::optional<Tok> pending;
    std::vector<std::string> filesRead;  // by Include and Import, in order
    uint64_t maxFileBytes;               // of any file (its contents, decompressed)
    FileLoc eofLoc;
    bool worldBegun = false;
    bool warnedTransformBegin = false, warnedTransformEnd = false;
};

}  // namespace

// Entry points
std::vector<std::string> ParseFile(ParserTarget& target, const std::string& filename,
                                   Diagnostics& diagnostics, uint64_t maxFileBytes) {
    std::string contents, error;
    if (!ReadFileContents(filename, &contents, &error, maxFileBytes))
        throw SceneError(FileLoc(std::make_shared<const std::string>(filename), 0, 0),
                         "cannot open scene file: " + error);
    target.FileContents(contents.size(),
                        FileLoc(std::make_shared<const std::string>(filename), 1, 1));
    SceneParser parser(target, diagnostics, SearchDirectoryFor(filename), maxFileBytes);
    parser.Run(std::move(contents), filename, FileKey(filename));
    target.EndOfFiles();
    std::vector<std::string> files = {filename};
    files.insert(files.end(), parser.FilesRead().begin(), parser.FilesRead().end());
    return files;
}

void ParseString(ParserTarget& target, std::string_view text, Diagnostics& diagnostics,
                 std::string_view pseudoFilename, const std::string& searchDirectory) {
    SceneParser parser(target, diagnostics, searchDirectory);
    parser.Run(std::string(text), std::string(pseudoFilename), "");
    target.EndOfFiles();
}

}  // namespace kiln
