#include "gpu/D3DCompileShaders.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <d3dcompiler.h>

#include <map>
#include <memory>

namespace firmament {

namespace {

using D3DCompileFunction = HRESULT(WINAPI*)(LPCVOID, SIZE_T, LPCSTR, const D3D_SHADER_MACRO*, ID3DInclude*, LPCSTR, LPCSTR,
                                            UINT, UINT, ID3DBlob**, ID3DBlob**);

// #include "x" resolves to root/x, whichever file includes it.
class RootIncludes final : public ID3DInclude {
public:
    explicit RootIncludes(const std::filesystem::path& root) : root_(root) {}

    HRESULT STDMETHODCALLTYPE Open(D3D_INCLUDE_TYPE, LPCSTR name, LPCVOID, LPCVOID* data, UINT* bytes) override {
        try {
            auto content = std::make_unique<std::vector<std::uint8_t>>(readFileBytes(root_ / name));
            *data = content->data();
            *bytes = static_cast<UINT>(content->size());
            open_[content->data()] = std::move(content);
            return S_OK;
        } catch (const Error&) {
            return E_FAIL;
        }
    }
    HRESULT STDMETHODCALLTYPE Close(LPCVOID data) override {
        open_.erase(data);
        return S_OK;
    }

private:
    std::filesystem::path root_;
    std::map<LPCVOID, std::unique_ptr<std::vector<std::uint8_t>>> open_;
};

std::string blobText(ID3DBlob* blob) {
    return blob ? std::string(static_cast<const char*>(blob->GetBufferPointer()), blob->GetBufferSize()) : std::string();
}

}  // namespace

bool D3DCompileShaders::available() {
    const HMODULE library = LoadLibraryW(L"d3dcompiler_47.dll");
    if (library) FreeLibrary(library);
    return library != nullptr;
}

D3DCompileShaders::D3DCompileShaders(std::filesystem::path root) : root_(std::move(root)) {
    library_ = LoadLibraryW(L"d3dcompiler_47.dll");
    if (library_) compile_ = reinterpret_cast<void*>(GetProcAddress(library_, "D3DCompile"));
    if (!compile_) throw Error("d3dcompiler_47.dll (D3DCompile) is not available on this system");
}

D3DCompileShaders::~D3DCompileShaders() {
    if (library_) FreeLibrary(library_);
}

CompileResult D3DCompileShaders::compile(const ShaderKey& key) {
    CompileResult result;
    const auto path = root_ / key.file;
    std::vector<std::uint8_t> source;
    try {
        source = readFileBytes(path);
    } catch (const Error& e) {
        result.log = e.what();
        return result;
    }
    std::vector<std::pair<std::string, std::string>> defineText;
    for (const std::string& d : key.defines) {
        const auto eq = d.find('=');
        defineText.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
    }
    std::vector<D3D_SHADER_MACRO> macros;
    for (const auto& [name, value] : defineText) macros.push_back({name.c_str(), value.c_str()});
    macros.push_back({nullptr, nullptr});

    RootIncludes includes(root_);
    ID3DBlob* code = nullptr;
    ID3DBlob* messages = nullptr;
    const std::string sourceName = path.string();
    const HRESULT hr = reinterpret_cast<D3DCompileFunction>(compile_)(
        source.data(), source.size(), sourceName.c_str(), macros.data(), &includes, key.entry.c_str(), key.profile.c_str(),
        D3DCOMPILE_ENABLE_STRICTNESS | D3DCOMPILE_OPTIMIZATION_LEVEL3, 0, &code, &messages);
    result.log = blobText(messages);
    if (SUCCEEDED(hr) && code) {
        const auto* bytes = static_cast<const std::uint8_t*>(code->GetBufferPointer());
        result.bytecode.assign(bytes, bytes + code->GetBufferSize());
        result.ok = true;
    } else if (result.log.empty()) {
        result.log = "D3DCompile failed (HRESULT " + std::to_string(static_cast<unsigned long>(hr)) + ")";
    }
    if (code) code->Release();
    if (messages) messages->Release();
    return result;
}

}  // namespace firmament
