// A ParserTarget that records every call as one line of text, for the parser tests.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "core/parser/parser_target.h"

namespace kiln {

class RecordingTarget : public ParserTarget {
  public:
    struct Call {
        std::string text;  // "Translate 1 2 3"
        FileLoc loc;
        ParsedParameterVector params;
    };
    std::vector<Call> calls;
    int endOfFiles = 0;

    // Call texts joined by '\n'.
    std::string Text() const {
        std::string s;
        for (const Call& c : calls) s += c.text + "\n";
        return s;
    }
    const Call& Find(const std::string& prefix) const {
        for (const Call& c : calls)
            if (c.text.rfind(prefix, 0) == 0) return c;
        static const Call none;
        return none;
    }

    static std::string N(Float f) {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%g", double(f));
        return buf;
    }
    void Add(std::string text, const FileLoc& loc, ParsedParameterVector params = {}) {
        calls.push_back({std::move(text), loc, std::move(params)});
    }
    template <size_t K>
    static std::string Ns(const std::array<Float, K>& v) {
        std::string s;
        for (Float f : v) {
            s += ' ';
            s += N(f);
        }
        return s;
    }

    void Identity(const FileLoc& l) override { Add("Identity", l); }
    void Translate(Float x, Float y, Float z, const FileLoc& l) override {
        Add("Translate " + N(x) + " " + N(y) + " " + N(z), l);
    }
    void Scale(Float x, Float y, Float z, const FileLoc& l) override {
        Add("Scale " + N(x) + " " + N(y) + " " + N(z), l);
    }
    void Rotate(Float a, Float x, Float y, Float z, const FileLoc& l) override {
        Add("Rotate " + N(a) + " " + N(x) + " " + N(y) + " " + N(z), l);
    }
    void LookAt(Float ex, Float ey, Float ez, Float lx, Float ly, Float lz, Float ux, Float uy,
                Float uz, const FileLoc& l) override {
        std::string s = "LookAt";
        s += Ns(std::array<Float, 9>{ex, ey, ez, lx, ly, lz, ux, uy, uz});
        Add(s, l);
    }
    void ConcatTransform(const std::array<Float, 16>& m, const FileLoc& l) override {
        Add(std::string("ConcatTransform") += Ns(m), l);
    }
    void Transform(const std::array<Float, 16>& m, const FileLoc& l) override {
        Add(std::string("Transform") += Ns(m), l);
    }
    void CoordinateSystem(const std::string& n, const FileLoc& l) override {
        Add("CoordinateSystem " + n, l);
    }
    void CoordSysTransform(const std::string& n, const FileLoc& l) override {
        Add("CoordSysTransform " + n, l);
    }
    void ActiveTransformAll(const FileLoc& l) override { Add("ActiveTransform All", l); }
    void ActiveTransformEndTime(const FileLoc& l) override { Add("ActiveTransform EndTime", l); }
    void ActiveTransformStartTime(const FileLoc& l) override {
        Add("ActiveTransform StartTime", l);
    }
    void TransformTimes(Float s, Float e, const FileLoc& l) override {
        Add("TransformTimes " + N(s) + " " + N(e), l);
    }
    void Option(const std::string& n, const std::string& v, const FileLoc& l) override {
        Add("Option " + n + " = " + v, l);
    }
    void ColorSpace(const std::string& n, const FileLoc& l) override { Add("ColorSpace " + n, l); }
    void PixelFilter(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("PixelFilter " + n, l, std::move(p));
    }
    void Film(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Film " + n, l, std::move(p));
    }
    void Accelerator(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Accelerator " + n, l, std::move(p));
    }
    void Integrator(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Integrator " + n, l, std::move(p));
    }
    void Camera(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Camera " + n, l, std::move(p));
    }
    void Sampler(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Sampler " + n, l, std::move(p));
    }
    void MakeNamedMedium(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("MakeNamedMedium " + n, l, std::move(p));
    }
    void MediumInterface(const std::string& in, const std::string& out, const FileLoc& l) override {
        Add("MediumInterface " + in + " " + out, l);
    }
    void WorldBegin(const FileLoc& l) override { Add("WorldBegin", l); }
    void AttributeBegin(const FileLoc& l) override { Add("AttributeBegin", l); }
    void AttributeEnd(const FileLoc& l) override { Add("AttributeEnd", l); }
    void Attribute(const std::string& t, ParsedParameterVector p, const FileLoc& l) override {
        Add("Attribute " + t, l, std::move(p));
    }
    void Shape(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Shape " + n, l, std::move(p));
    }
    void ReverseOrientation(const FileLoc& l) override { Add("ReverseOrientation", l); }
    void Texture(const std::string& n, const std::string& t, const std::string& c,
                 ParsedParameterVector p, const FileLoc& l) override {
        Add("Texture " + n + " " + t + " " + c, l, std::move(p));
    }
    void Material(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("Material " + n, l, std::move(p));
    }
    void MakeNamedMaterial(const std::string& n, ParsedParameterVector p,
                           const FileLoc& l) override {
        Add("MakeNamedMaterial " + n, l, std::move(p));
    }
    void NamedMaterial(const std::string& n, const FileLoc& l) override {
        Add("NamedMaterial " + n, l);
    }
    void LightSource(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("LightSource " + n, l, std::move(p));
    }
    void AreaLightSource(const std::string& n, ParsedParameterVector p, const FileLoc& l) override {
        Add("AreaLightSource " + n, l, std::move(p));
    }
    void ObjectBegin(const std::string& n, const FileLoc& l) override {
        Add("ObjectBegin " + n, l);
    }
    void ObjectEnd(const FileLoc& l) override { Add("ObjectEnd", l); }
    void ObjectInstance(const std::string& n, const FileLoc& l) override {
        Add("ObjectInstance " + n, l);
    }
    void EndOfFiles() override { ++endOfFiles; }
};

}  // namespace kiln
