// The Python module ssfx._ssfx (pybind11): the library on numpy arrays. The package
// python/ssfx/ re-exports it as ssfx, ssfx.ao, ssfx.io and ssfx.metrics (docs/python.md).
//
// Every argument is taken as a Python object and checked here, before anything reaches the
// library, with Python's split: a wrong type raises TypeError, a bad value (dtype, shape,
// size, range, a parameter) ssfx.Error (a ValueError); both short, in ssfx's words, naming
// the argument (never pybind11's signature dump or a RuntimeError). numpy scalars are
// numbers; paths are str or os.PathLike. The library's own errors (ssfx::Error) become
// ssfx.Error too. Nothing can abort the interpreter. The GIL is released while a method runs.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "ssfx/aa/presets.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/ao/registry.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/io/camera.hpp"
#include "ssfx/io/exr.hpp"
#include "ssfx/io/png.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/gpu/aa.hpp"
#include "ssfx/gpu/ao.hpp"
#endif

namespace py = pybind11;
using namespace ssfx;

namespace {

// ---- arguments ------------------------------------------------------------------------------
std::string typeName(const py::handle& v) { return py::str(py::type::handle_of(v).attr("__name__")); }

[[noreturn]] void wrongType(const std::string& arg, const char* expected, const py::handle& v) {
    throw py::type_error(fmt::format("{}: expected {}, not {}", arg, expected, typeName(v)));
}

std::string strArg(const py::handle& v, const std::string& arg) {
    if (!py::isinstance<py::str>(v)) wrongType(arg, "a str", v);
    return v.cast<std::string>();
}

std::optional<std::string> optionalStrArg(const py::handle& v, const std::string& arg) {
    if (v.is_none()) return std::nullopt;
    return strArg(v, arg);
}

// A file path: str or os.PathLike (pathlib.Path); a NUL byte in it is refused by the io layer.
std::string pathArg(const py::handle& v, const std::string& arg) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::hasattr(v, "__fspath__")) {
        const py::object p = py::module_::import("os").attr("fspath")(v);
        if (py::isinstance<py::str>(p)) return p.cast<std::string>();
        if (py::isinstance<py::bytes>(p)) return p.cast<std::string>();
    }
    if (py::isinstance<py::bytes>(v)) return v.cast<std::string>();
    wrongType(arg, "a path (str or os.PathLike)", v);
}

bool isNumpyScalar(const py::handle& v, const char* kind) {
    return py::isinstance(v, py::module_::import("numpy").attr(kind));
}

// A whole number: int or a numpy integer (not bool, not float: 2.5 threads is a type error).
std::int64_t intArg(const py::handle& v, const std::string& arg, std::int64_t lo, std::int64_t hi) {
    if (PyBool_Check(v.ptr()) || isNumpyScalar(v, "bool_") || !PyIndex_Check(v.ptr())) wrongType(arg, "an int", v);
    const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
    if (!i) throw py::error_already_set();
    int overflow = 0;
    const long long n = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
    if (overflow != 0 || n < lo || n > hi)
        throw Error(fmt::format("{}: {} is not in [{}, {}]", arg, std::string(py::str(i)), lo, hi));
    return n;
}

// A number: bool, int, float or a numpy scalar of those kinds; nullopt for any other type.
// An int too large for a double (10**400) is a bad value, not a type error.
std::optional<double> numberOf(const py::handle& v, const std::string& arg) {
    PyObject* o = v.ptr();
    if (PyBool_Check(o) || isNumpyScalar(v, "bool_")) return PyObject_IsTrue(o) ? 1.0 : 0.0;
    if (PyIndex_Check(o)) {
        const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(o));
        if (!i) throw py::error_already_set();
        const double d = PyLong_AsDouble(i.ptr());
        if (d == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            const std::string digits = py::str(i);
            throw Error(
                fmt::format("{}: {} ({} digits) is too large", arg, digits.substr(0, 12) + "...", digits.size()));
        }
        return d;
    }
    if (PyFloat_Check(o) || isNumpyScalar(v, "floating")) {
        const double d = PyFloat_AsDouble(o);
        if (d == -1.0 && PyErr_Occurred()) throw py::error_already_set();
        return d;
    }
    return std::nullopt;
}

double floatArg(const py::handle& v, const std::string& arg) {
    if (PyBool_Check(v.ptr())) wrongType(arg, "a number", v);
    const std::optional<double> d = numberOf(v, arg);
    if (!d) wrongType(arg, "a number", v);
    return *d;
}

py::array arrayArg(const py::handle& v, const std::string& arg) {
    if (!py::isinstance<py::array>(v)) wrongType(arg, "a numpy array", v);
    return py::reinterpret_borrow<py::array>(v);
}

int threadsArg(const py::handle& v) { return int(intArg(v, "threads", 0, 1024)); }

// ---- arrays <-> image views ---------------------------------------------------------------
// An (H, W, C) uint8 array seen as RGBA8 rows: a view without a copy when C is 4, the
// channels are adjacent bytes and each row starts on a whole pixel (any row pitch, so
// slices and crops of a bigger image qualify); otherwise a packed RGBA copy (alpha 255
// for C = 3).
struct RgbaInput {
    ImageRgba8 copy;  // empty when `view` looks into the array
    ImageView<const Rgba8> view;
    int channels = 4;
};

void checkImageArray(const py::array& a, const char* arg) {
    if (!py::dtype::of<std::uint8_t>().is(a.dtype()))
        throw Error(fmt::format("{}: dtype {} is not uint8", arg, std::string(py::str(a.dtype()))));
    if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4))
        throw Error(fmt::format(
            "{}: shape {} is not (height, width, 3) or (height, width, 4)", arg,
            std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim())))))));
    checkDimensions(a.shape(1), a.shape(0), arg);
}

bool viewable(const py::array& a) {
    return a.shape(2) == 4 && a.strides(2) == 1 && a.strides(1) == 4 && a.strides(0) > 0 && a.strides(0) % 4 == 0 &&
           reinterpret_cast<std::uintptr_t>(a.data()) % alignof(Rgba8) == 0;
}

RgbaInput rgbaInput(const py::array& a, const char* arg) {
    checkImageArray(a, arg);
    RgbaInput in;
    const int h = int(a.shape(0)), w = int(a.shape(1)), c = int(a.shape(2));
    in.channels = c;
    if (viewable(a)) {
        in.view = ImageView<const Rgba8>(static_cast<const Rgba8*>(a.data()), w, h, a.strides(0) / 4);
        return in;
    }
    in.copy = ImageRgba8(w, h);
    const auto* base = static_cast<const std::uint8_t*>(a.data());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = base + y * a.strides(0) + x * a.strides(1);
            std::uint8_t v[4] = {0, 0, 0, 255};
            for (int k = 0; k < c; ++k) v[k] = p[k * a.strides(2)];
            in.copy(x, y) = {v[0], v[1], v[2], v[3]};
        }
    in.view = in.copy.view();
    return in;
}

// Writes `img` into the (H, W, C) uint8 array `out` (any strides), dropping alpha for C = 3.
void copyInto(ImageView<const Rgba8> img, py::array& out) {
    auto* base = static_cast<std::uint8_t*>(out.mutable_data());
    const int c = int(out.shape(2));
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgba8 p = img(x, y);
            const std::uint8_t v[4] = {p.r, p.g, p.b, p.a};
            std::uint8_t* q = base + y * out.strides(0) + x * out.strides(1);
            for (int k = 0; k < c; ++k) q[k * out.strides(2)] = v[k];
        }
}

// The bytes an array spans (any strides, negative ones too).
std::pair<const char*, const char*> byteRange(const py::array& a) {
    const char* lo = static_cast<const char*>(a.data());
    const char* hi = lo;
    for (py::ssize_t d = 0; d < a.ndim(); ++d) {
        const py::ssize_t span = (a.shape(d) - 1) * a.strides(d);
        (span < 0 ? lo : hi) += span;
    }
    return {lo, hi + a.itemsize()};
}

bool overlaps(const py::array& a, const py::array& b) {
    const auto [a0, a1] = byteRange(a);
    const auto [b0, b1] = byteRange(b);
    return a0 < b1 && b0 < a1;
}

py::array_t<std::uint8_t> newImageArray(int w, int h, int channels) {
    return py::array_t<std::uint8_t>({py::ssize_t(h), py::ssize_t(w), py::ssize_t(channels)});
}

py::array_t<std::uint8_t> toArray(ImageView<const Rgba8> img, int channels) {
    auto a = newImageArray(img.width(), img.height(), channels);
    py::array ref = a;
    copyInto(img, ref);
    return a;
}

// ---- parameters -----------------------------------------------------------------------
// A keyword argument as the method's table takes it: a number, a bool, or a string (a
// Choice's name, "true"/"false", a number as text).
double paramValue(const ParamInfo& row, const py::handle& v, std::string_view id) {
    const std::string arg = fmt::format("{}: parameter {}", id, row.name);
    if (py::isinstance<py::str>(v)) return parseParamValue(row, v.cast<std::string>(), id);
    if (const std::optional<double> d = numberOf(v, arg)) return *d;
    wrongType(arg, "a number, a bool or a str", v);
}

std::vector<std::pair<std::string, double>> paramList(std::span<const ParamInfo> table, std::string_view id,
                                                      const py::kwargs& kwargs,
                                                      std::initializer_list<std::string_view> skip = {}) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& [k, v] : kwargs) {
        const std::string name = k.cast<std::string>();
        if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        const ParamInfo& row = findParam(table, id, name);
        const double value = paramValue(row, v, id);
        checkParam(row, value, id);
        out.emplace_back(name, value);
    }
    return out;
}

// ---- ssfx.aa ------------------------------------------------------------------------------
#ifdef SSFX_HAVE_GPU
// backend='vulkan': one Vulkan context per process and device choice, made when first needed
// (as the CLI's --backend vulkan: the same device choice and the same passes, so the same
// bytes). A context is used by one thread at a time: its mutex. The map is never freed: the
// contexts live until the process ends, past Python's own teardown.
struct GpuContext {
    std::shared_ptr<vkx::Context> ctx;
    std::mutex mutex;
};
GpuContext& gpuContext(const std::string& device) {
    static std::mutex mutex;
    static auto* contexts = new std::map<std::string, std::unique_ptr<GpuContext>>;
    std::lock_guard lock(mutex);
    if (const auto it = contexts->find(device); it != contexts->end()) return *it->second;
    vkx::ContextOptions o;
    o.device = device;
    auto g = std::make_unique<GpuContext>();
    try {
        g->ctx = vkx::Context::create(o);
    } catch (const Error& e) {
        throw Error(fmt::format("backend='vulkan' looked for a Vulkan 1.3 device with a compute queue{}: {}",
                                device.empty() ? "" : fmt::format(" matching '{}'", device), e.what()));
    }
    return *contexts->emplace(device, std::move(g)).first->second;
}
#endif

// An array whose elements do not overlap one another: sorted by stride, each dimension's
// stride must step past everything the smaller ones span (as_strided's (4, 4, 1) or
// (0, 0, 1) would have several output pixels share bytes, and their writes would race).
bool selfOverlapping(const py::array& a) {
    std::vector<std::pair<py::ssize_t, py::ssize_t>> dims;  // |stride|, extent
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
        if (a.shape(d) > 1) dims.emplace_back(a.strides(d) < 0 ? -a.strides(d) : a.strides(d), a.shape(d));
    std::sort(dims.begin(), dims.end());
    py::ssize_t span = a.itemsize();  // bytes covered by the dimensions so far
    for (const auto& [stride, extent] : dims) {
        if (stride < span) return true;
        span = stride * (extent - 1) + span;
    }
    return false;
}

py::object runAa(const py::handle& imageArg, const py::handle& methodArg, const py::handle& presetArg,
                 const py::handle& threadsArg_, const py::handle& filteringArg, const py::handle& outArg,
                 const py::handle& backendArg, const py::handle& deviceArg, const py::kwargs& kwargs) {
    const py::array image = arrayArg(imageArg, "image");
    const std::string method = strArg(methodArg, "method");
    const std::optional<std::string> preset = optionalStrArg(presetArg, "preset");
    const int threads = threadsArg(threadsArg_);
    const std::string filtering = strArg(filteringArg, "filtering");
    const std::optional<py::array> out =
        outArg.is_none() ? std::nullopt : std::optional<py::array>(arrayArg(outArg, "out"));
    const std::string backend = strArg(backendArg, "backend");
    if (backend != "cpu" && backend != "vulkan")
        throw Error(fmt::format("backend: '{}' is not cpu or vulkan", backend));
    const std::optional<std::string> device = optionalStrArg(deviceArg, "device");
    if (device && backend != "vulkan") throw Error("device: goes with backend='vulkan'");
    // The vulkan backend's own choices, as the CLI's -p sampling=... and -p edges=....
    std::string sampling = "model", edges = "auto";
    for (const char* name : {"sampling", "edges"})
        if (kwargs.contains(name)) {
            if (backend != "vulkan") throw Error(fmt::format("{}: a choice of backend='vulkan'", name));
            (std::string_view(name) == "sampling" ? sampling : edges) = strArg(kwargs[name], name);
        }
    const MethodInfo& m = methodById(method);
    MethodSettings s;
    if (preset) {
        if (!m.usesPresets) throw Error(fmt::format("{}: this method has no edge-threshold presets", method));
        s.preset = aa::parsePreset(*preset);
        if (!s.preset)
            throw Error(fmt::format("preset: unknown preset '{}' (low, medium, high, ultra, extreme)", *preset));
    }
    if (filtering == "exact")
        s.filtering = Filtering::Exact;
    else if (filtering != "gpu")
        throw Error(fmt::format("filtering: '{}' is not gpu or exact", filtering));
    s.params = paramList(m.params, method, kwargs, {"sampling", "edges"});
    const Exec exec{threads};
    RgbaInput in = rgbaInput(image, "image");
    const int scale = m.inputScale;
    if (in.view.width() % scale != 0 || in.view.height() % scale != 0)
        throw Error(fmt::format("image: size {}x{} is not divisible by {} ({} takes the {}x render)", in.view.width(),
                                in.view.height(), scale, method, scale));
    const int ow = in.view.width() / scale, oh = in.view.height() / scale;

    py::array result;
    if (out) {
        result = *out;
        checkImageArray(result, "out");
        if (result.shape(0) != oh || result.shape(1) != ow || result.shape(2) != in.channels)
            throw Error(fmt::format("out: shape ({}, {}, {}) is not ({}, {}, {}), the output's", result.shape(0),
                                    result.shape(1), result.shape(2), oh, ow, in.channels));
        if (!result.writeable()) throw Error("out: the array is read-only");
        if (selfOverlapping(result))
            throw Error("out: its elements overlap one another (strides that step back into the array)");
        if (overlaps(result, image))  // the methods read neighbours of what they write
            throw Error("out: must not overlap the image (not even be the image: give a new array)");
    } else {
        result = newImageArray(ow, oh, in.channels);
    }
    if (backend == "vulkan") {
#ifdef SSFX_HAVE_GPU
        const gpu::Sampling mode = gpu::parseSampling(sampling);
        const gpu::EdgePath path = gpu::parseEdgePath(edges);
        GpuContext& g = gpuContext(device.value_or(""));
        ImageRgba8 tmp;
        {
            py::gil_scoped_release release;
            std::lock_guard lock(g.mutex);
            gpu::AaPass pass(g.ctx, method, s, mode, path);
            tmp = pass.run(in.view);
        }
        copyInto(tmp.view(), result);
        return result;
#else
        throw Error("backend: this ssfx was built without the GPU backend (SSFX_BUILD_GPU=OFF); use backend='cpu'");
#endif
    }
    if (in.channels == 4 && viewable(result)) {
        ImageView<Rgba8> dst(static_cast<Rgba8*>(result.mutable_data()), ow, oh, result.strides(0) / 4);
        py::gil_scoped_release release;
        m.runInto(in.view, dst, s, exec);
    } else {
        ImageRgba8 tmp(ow, oh);
        {
            py::gil_scoped_release release;
            m.runInto(in.view, tmp.view(), s, exec);
        }
        copyInto(tmp.view(), result);
    }
    return result;
}

// ---- ssfx.methods ---------------------------------------------------------------------------
py::dict paramDict(const ParamInfo& p) {
    py::dict d;
    d["name"] = std::string(p.name);
    d["kind"] = std::string(kindName(p.kind));
    d["unit"] = std::string(p.unit);
    d["doc"] = std::string(p.doc);
    d["range"] = p.rangeText();
    if (p.kind == ParamKind::Choice) {
        py::list names;
        for (auto c : p.choices) names.append(std::string(c));
        d["choices"] = names;
        d["default"] = std::string(p.choices[std::size_t(p.defaultValue())]);
    } else if (p.kind == ParamKind::Boolean) {
        d["default"] = p.defaultValue() != 0;
    } else if (p.kind == ParamKind::Integer) {
        d["default"] = std::int64_t(p.defaultValue());
        d["min"] = std::int64_t(p.min), d["max"] = std::int64_t(p.max);
    } else {
        // The shortest text that reads back as the member's value (0.6, not 0.60000002).
        d["default"] = std::stod(p.valueText(p.defaultValue()));
        d["min"] = p.min, d["max"] = p.max;
    }
    return d;
}

py::dict methodDict(const MethodDesc& m) {
    py::dict d;
    d["id"] = std::string(m.id);
    d["family"] = std::string(m.family);
    d["summary"] = std::string(m.summary);
    d["citation"] = std::string(m.citation);
    d["inputs"] = std::string(m.inputs);
    py::list params, presets;
    for (const ParamInfo& p : m.params) params.append(paramDict(p));
    for (auto p : m.presets) presets.append(std::string(p));
    d["params"] = params;
    d["presets"] = presets;
    return d;
}

py::list listMethods(const py::handle& familyArg) {
    const std::optional<std::string> family = optionalStrArg(familyArg, "family");
    if (family && *family != "aa" && *family != "ao") throw Error(fmt::format("family: '{}' is not aa or ao", *family));
    py::list out;
    if (!family || *family == "aa")
        for (const MethodInfo& m : methods()) {
            py::dict d = methodDict(m);
            d["input_scale"] = m.inputScale;
            out.append(d);
        }
    if (!family || *family == "ao")
        for (const ao::AoMethodInfo& m : ao::aoMethods()) out.append(methodDict(m));
    return out;
}

// ---- ssfx.ao ----------------------------------------------------------------------------
py::array_t<float> floatArray(const ImageF& a) {
    py::array_t<float> out({py::ssize_t(a.height()), py::ssize_t(a.width())});
    for (int y = 0; y < a.height(); ++y)
        std::memcpy(out.mutable_data(y, 0), a.view().row(y), std::size_t(a.width()) * 4);
    return out;
}

// A (H, W) float32 array as an image view (rows of adjacent floats), else copied into `copy`.
ImageView<const float> floatView(const py::array& a, const char* arg, ImageF& copy) {
    if (!py::dtype::of<float>().is(a.dtype()))
        throw Error(fmt::format("{}: dtype {} is not float32", arg, std::string(py::str(a.dtype()))));
    if (a.ndim() != 2) throw Error(fmt::format("{}: {} dimensions, expected 2 (height, width)", arg, a.ndim()));
    checkDimensions(a.shape(1), a.shape(0), arg);
    const int h = int(a.shape(0)), w = int(a.shape(1));
    if (a.strides(1) == 4 && a.strides(0) > 0 && a.strides(0) % 4 == 0)
        return ImageView<const float>(static_cast<const float*>(a.data()), w, h, a.strides(0) / 4);
    copy = ImageF(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            std::memcpy(&copy(x, y), static_cast<const char*>(a.data()) + y * a.strides(0) + x * a.strides(1), 4);
    return copy.view();
}
Camera cameraFrom(const py::handle& camera) {
    if (py::isinstance<py::str>(camera) || py::hasattr(camera, "__fspath__"))
        return io::readCameraJson(pathArg(camera, "camera"));
    if (!py::isinstance<py::dict>(camera))
        wrongType("camera", "a dict {'fov_y_deg': ..., 'z_near': ..., 'z_far': ...} or a camera .json path", camera);
    // The same keys, checks and messages as a camera file (io/camera.hpp), from a dict of
    // plain values: numbers (numpy's too) as finite floats, None, and str.
    py::dict plain;
    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(camera)) {
        const std::string key = strArg(k, "camera key");
        const std::string arg = fmt::format("camera: '{}'", key);
        if (v.is_none() || py::isinstance<py::str>(v)) {
            plain[k] = v;
        } else if (const std::optional<double> d = PyBool_Check(v.ptr()) ? std::nullopt : numberOf(v, arg)) {
            if (!std::isfinite(*d)) throw Error(fmt::format("{} is {}, not a finite number", arg, *d));
            plain[k] = *d;
        } else {
            wrongType(arg, "a number", v);
        }
    }
    const std::string text = py::module_::import("json").attr("dumps")(plain).cast<std::string>();
    return io::parseCameraJson(text, "camera");
}

py::array_t<float> runAo(const char* id, const py::handle& depthArg, const py::handle& camera,
                         const py::handle& presetArg, const py::handle& threadsArg_, const py::handle& backendArg,
                         const py::handle& deviceArg, const py::kwargs& kwargs) {
    const py::array depth = arrayArg(depthArg, "depth");
    const std::optional<std::string> preset = optionalStrArg(presetArg, "preset");
    const int threads = threadsArg(threadsArg_);
    const std::string backend = strArg(backendArg, "backend");
    if (backend != "cpu" && backend != "vulkan")
        throw Error(fmt::format("backend: '{}' is not cpu or vulkan", backend));
    const std::optional<std::string> device = optionalStrArg(deviceArg, "device");
    if (device && backend != "vulkan") throw Error("device: goes with backend='vulkan'");
    const ao::AoMethodInfo& m = ao::aoMethodById(id);
    ImageF copy;
    const ImageView<const float> view = floatView(depth, "depth", copy);
    const Camera cam = cameraFrom(camera);
    ao::AoParams params = m.defaults(preset.value_or(""));
    for (const auto& [name, value] : paramList(m.params, id, kwargs)) ao::setParam(m, params, name, value);
    m.validate(params);
    const Exec exec{threads};
    ImageF a;
    if (backend == "vulkan") {
#ifdef SSFX_HAVE_GPU
        if (!gpu::hasGpuAo(id))
            throw Error(fmt::format("backend: {} has no GPU pass (backend='vulkan' runs sao, alchemy and gtao)", id));
        GpuContext& g = gpuContext(device.value_or(""));
        ao::depthToZ(view, cam, exec);  // the CPU's checks and messages, before any GPU work
        py::gil_scoped_release release;
        std::lock_guard lock(g.mutex);
        a = gpu::AoPass(g.ctx, id, params).run(view, cam);
#else
        throw Error("backend: this ssfx was built without the GPU backend (SSFX_BUILD_GPU=OFF); use backend='cpu'");
#endif
    } else {
        py::gil_scoped_release release;
        a = m.run(ao::AoInput{view, cam, nullptr, {}, {}}, params, exec);
    }
    return floatArray(a);
}

// ---- ssfx.io ----------------------------------------------------------------------------------

py::list readApngFrames(const py::handle& pathArg_) {
    const io::Animation anim = io::readApng(pathArg(pathArg_, "path"));
    py::list frames;
    for (const io::Frame& f : anim.frames) frames.append(py::make_tuple(toArray(f.image.view(), 4), f.delaySeconds()));
    return frames;
}

void writeApngFrames(const py::handle& pathArg_, const py::handle& framesArg, const py::handle& fpsArg) {
    const std::string path = pathArg(pathArg_, "path");
    if (!py::isinstance<py::list>(framesArg) && !py::isinstance<py::tuple>(framesArg))
        wrongType("frames", "a list of arrays", framesArg);
    const py::sequence frames = py::reinterpret_borrow<py::sequence>(framesArg);
    const double fps = floatArg(fpsArg, "fps");
    // Delays are stored in milliseconds (16 bits): 1000 fps down to one frame a minute.
    if (!(fps >= 1.0 / 60.0 && fps <= 1000)) throw Error(fmt::format("fps: {} is not in [1/60, 1000]", fps));
    if (frames.size() == 0) throw Error("frames: empty (an APNG needs a frame)");
    io::Animation anim;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const py::array a = arrayArg(frames[i], fmt::format("frames[{}]", i));
        const RgbaInput in = rgbaInput(a, fmt::format("frames[{}]", i).c_str());
        io::Frame f;
        f.image = ImageRgba8(in.view.width(), in.view.height());
        for (int y = 0; y < in.view.height(); ++y)
            std::memcpy(f.image.view().row(y), in.view.row(y), std::size_t(in.view.width()) * 4);
        // The delay as a fraction of whole milliseconds (APNG: 16-bit numerator and denominator).
        f.delayNum = std::uint16_t(std::max(1.0, std::round(1000.0 / fps)));
        f.delayDen = 1000;
        if (!anim.frames.empty() && (f.image.width() != anim.width() || f.image.height() != anim.height()))
            throw Error(fmt::format("frames[{}]: {}x{}, not the first frame's {}x{}", i, f.image.width(),
                                    f.image.height(), anim.width(), anim.height()));
        anim.frames.push_back(std::move(f));
    }
    io::writeApng(path, anim);
}

// A metric of two images of one size (3 or 4 channels each; RGB compared).
double pairMetric(const py::handle& a, const py::handle& b,
                  double (*metric)(ImageView<const Rgba8>, ImageView<const Rgba8>, const Exec&)) {
    const RgbaInput x = rgbaInput(arrayArg(a, "a"), "a"), y = rgbaInput(arrayArg(b, "b"), "b");
    if (x.view.width() != y.view.width() || x.view.height() != y.view.height())
        throw Error(fmt::format("a and b: not the same size ({}x{} and {}x{})", x.view.width(), x.view.height(),
                                y.view.width(), y.view.height()));
    return metric(x.view, y.view, Exec{});
}

std::string methodsDoc() {
    std::string s =
        "Anti-aliases an image (a new array unless `out` is given).\n\n"
        "image: (H, W, 4) or (H, W, 3) uint8 (3 channels: alpha 255 is added, 3 are returned); any strides.\n"
        "method: one of the ids below; preset: low, medium (default), high, ultra, extreme (threshold methods);\n"
        "threads: 0 = all (the bytes do not depend on it); filtering: 'gpu' (default) or 'exact';\n"
        "out: an array of the output's shape to write into; **params: the method's parameters.\n"
        "backend: 'cpu' (default) or 'vulkan' (the Vulkan compute pass, on one context per process made when first\n"
        "needed: the CPU's bytes with sampling='model', the default; sampling='hardware': the device's filtering\n"
        "and arithmetic; edges='list'|'one-pass'|'segments': the path of blur and the edge methods, default 'auto'); "
        "device: with "
        "'vulkan',\n"
        "a device index or part of its name, as the CLI's --device (default: a GPU, else lavapipe).\n\nMethods:\n";
    for (const MethodInfo& m : methods()) {
        s += fmt::format("  {}: {}\n", m.id, m.summary);
        for (const ParamInfo& p : m.params)
            s += fmt::format("      {}={} ({}): {}\n", p.name, p.valueText(p.defaultValue()), p.rangeText(), p.doc);
    }
    return s;
}

}  // namespace

PYBIND11_MODULE(_ssfx, m) {
    m.doc() = "ssfx: screen-space rendering effects on numpy arrays (docs/python.md)";
    py::register_exception<Error>(m, "Error", PyExc_ValueError);
    m.def("aa", &runAa, py::arg("image"), py::arg("method") = "ddaa2", py::arg("preset") = py::none(),
          py::arg("threads") = 0, py::arg("filtering") = "gpu", py::arg("out") = py::none(), py::arg("backend") = "cpu",
          py::arg("device") = py::none(), methodsDoc().c_str());
    m.def(
        "resample",
        [](const py::handle& image, const py::handle& factorArg, const py::handle& threads) {
            const RgbaInput in = rgbaInput(arrayArg(image, "image"), "image");
            const int factor = int(intArg(factorArg, "factor", -64, 64));
            const Exec exec{threadsArg(threads)};
            ImageRgba8 out;
            {
                py::gil_scoped_release release;
                out = aa::resampleMitchell(in.view, factor, {}, exec);
            }
            return toArray(out.view(), in.channels);
        },
        py::arg("image"), py::arg("factor"), py::arg("threads") = 0,
        "Mitchell-Netravali resampling (B = C = 1/3) by an integer factor: factor > 1 shrinks (8: an x8 drawing "
        "resolved to 1x, the evaluation's truth), factor < -1 magnifies by -factor.");
    m.def("methods", &listMethods, py::arg("family") = py::none(),
          "Every method of a family ('aa', 'ao'; default both): id, family, summary, citation, inputs, params "
          "(name, kind, unit, default, min/max or choices, range, doc), presets.");
    // One function per AO method that reads a depth buffer, from the registry: ssfx.ao.sao,
    // ssfx.ao.alchemy, ssfx.ao.gtao (the ray-traced truth needs the scene's geometry).
    for (const ao::AoMethodInfo& method : ao::aoMethods()) {
        if (method.needsGeometry) continue;
        std::string presets = "None (the defaults)";
        for (std::string_view pr : method.presets) presets += fmt::format(", '{}'", pr);
        const std::string doc = fmt::format(
            "{} ({}). depth: (H, W) float32 depth-buffer values in [0, 1]; camera: a dict {{'fov_y_deg', 'z_near', "
            "'z_far'}} or a camera .json path; returns visibility (H - 2g, W - 2g) float32 (g = guardBand). "
            "preset: {}. The method's parameters by name as keywords (ssfx.methods('ao'), "
            "docs/methods/{}.md). backend: 'cpu' (default) or 'vulkan' (sao, alchemy, gtao: the GPU passes on one "
            "context per process and device, made when first needed; the same result as the CLI's --backend "
            "vulkan); device: with 'vulkan', an index or part of a name.",
            method.summary, method.citation, presets, method.id);
        const std::string id(method.id);
        m.def(
            id.c_str(),
            [id](const py::handle& d, const py::handle& c, const py::handle& preset, const py::handle& threads,
                 const py::handle& backend, const py::handle& device,
                 const py::kwargs& kw) { return runAo(id.c_str(), d, c, preset, threads, backend, device, kw); },
            py::arg("depth"), py::arg("camera"), py::arg("preset") = py::none(), py::arg("threads") = 0,
            py::arg("backend") = "cpu", py::arg("device") = py::none(), doc.c_str());
    }
    m.def(
        "read_png", [](const py::handle& path) { return toArray(io::readPng(pathArg(path, "path")).view(), 4); },
        py::arg("path"), "A PNG as (H, W, 4) uint8.");
    m.def(
        "write_png",
        [](const py::handle& path, const py::handle& image) {
            const std::string file = pathArg(path, "path");
            const RgbaInput in = rgbaInput(arrayArg(image, "image"), "image");
            io::writePng(file, in.view);
        },
        py::arg("path"), py::arg("image"), "Writes (H, W, 3|4) uint8 as RGBA PNG, atomically.");
    m.def(
        "read_exr",
        [](const py::handle& path, const py::handle& channel) {
            return floatArray(io::readExr(pathArg(path, "path"), strArg(channel, "channel")));
        },
        py::arg("path"), py::arg("channel") = "",
        "One channel of an OpenEXR file as (H, W) float32 (channel '' = the only one, or Z, Y, R).");
    m.def(
        "write_exr",
        [](const py::handle& path, const py::handle& image, const py::handle& channel) {
            const std::string file = pathArg(path, "path");
            ImageF copy;
            const ImageView<const float> view = floatView(arrayArg(image, "image"), "image", copy);
            io::writeExr(file, view, strArg(channel, "channel"));
        },
        py::arg("path"), py::arg("image"), py::arg("channel") = "Y", "Writes (H, W) float32 as a one-channel OpenEXR.");
    m.def("read_apng", &readApngFrames, py::arg("path"), "An APNG's frames: a list of ((H, W, 4) uint8, delay s).");
    m.def("write_apng", &writeApngFrames, py::arg("path"), py::arg("frames"), py::arg("fps") = 25.0,
          "Writes frames (a list of (H, W, 3|4) uint8 of one size) as a looping APNG, atomically.");
    m.def(
        "psnr", [](const py::handle& a, const py::handle& b) { return pairMetric(a, b, eval::psnr); }, py::arg("a"),
        py::arg("b"), "PSNR in dB over RGB in [0, 1] (inf when equal).");
    m.def(
        "ssim", [](const py::handle& a, const py::handle& b) { return pairMetric(a, b, eval::ssim); }, py::arg("a"),
        py::arg("b"), "SSIM on non-overlapping 8x8 windows, mean over RGB (docs/evaluation.md).");
    m.def(
        "score_x8",
        [](const py::handle& output, const py::handle& render8x, const py::handle& threadsArg_) {
            const RgbaInput x = rgbaInput(arrayArg(output, "output"), "output"),
                            y = rgbaInput(arrayArg(render8x, "render8x"), "render8x");
            if (std::int64_t(x.view.width()) * 8 != y.view.width() ||
                std::int64_t(x.view.height()) * 8 != y.view.height())
                throw Error(fmt::format("render8x: {}x{}, not 8 times the output's {}x{}", y.view.width(),
                                        y.view.height(), x.view.width(), x.view.height()));
            const Exec exec{threadsArg(threadsArg_)};
            eval::Score sc;
            {
                py::gil_scoped_release release;
                sc = eval::scoreAgainstX8(x.view, y.view, exec);
            }
            return py::make_tuple(sc.psnr, sc.ssim);
        },
        py::arg("output"), py::arg("render8x"), py::arg("threads") = 0,
        "The DDAA paper's protocol: (PSNR, SSIM) of a 1x output upscaled x8 (Mitchell) against the x8 render.");
}
