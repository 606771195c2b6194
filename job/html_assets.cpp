#include "job/html_assets.hpp"

// Each file becomes a hidden read-only symbol pair (start, end) with the assembler's .incbin;
// the paths come from tools/CMakeLists.txt, which also makes this file depend on them.
#define TUBEMESH_INCBIN(name, path)                                                                         \
    __asm__(".section .rodata\n.balign 16\n.hidden " #name "\n.globl " #name "\n" #name ":\n.incbin \"" path \
            "\"\n.hidden " #name "_end\n.globl " #name "_end\n" #name "_end:\n.byte 0\n.previous\n");       \
    extern "C" const char name[];                                                                           \
    extern "C" const char name##_end[];

TUBEMESH_INCBIN(tubemesh_three_js, TUBEMESH_THREE_JS)
TUBEMESH_INCBIN(tubemesh_orbit_controls_js, TUBEMESH_ORBIT_CONTROLS_JS)
TUBEMESH_INCBIN(tubemesh_chart_js, TUBEMESH_CHART_JS)
TUBEMESH_INCBIN(tubemesh_page_js, TUBEMESH_PAGE_JS)
TUBEMESH_INCBIN(tubemesh_page_css, TUBEMESH_PAGE_CSS)
TUBEMESH_INCBIN(tubemesh_page_body, TUBEMESH_PAGE_BODY)
TUBEMESH_INCBIN(tubemesh_batch_js, TUBEMESH_BATCH_JS)
TUBEMESH_INCBIN(tubemesh_batch_body, TUBEMESH_BATCH_BODY)

namespace tubemesh::job {

namespace {
std::string_view between(const char* begin, const char* end) {
    return {begin, static_cast<std::size_t>(end - begin)};
}
}  // namespace

const HtmlAssets& html_assets() {
    static const HtmlAssets assets{
        between(tubemesh_three_js, tubemesh_three_js_end),
        between(tubemesh_orbit_controls_js, tubemesh_orbit_controls_js_end),
        between(tubemesh_chart_js, tubemesh_chart_js_end),
        between(tubemesh_page_js, tubemesh_page_js_end),
        between(tubemesh_page_css, tubemesh_page_css_end),
        between(tubemesh_page_body, tubemesh_page_body_end),
        between(tubemesh_batch_js, tubemesh_batch_js_end),
        between(tubemesh_batch_body, tubemesh_batch_body_end),
    };
    return assets;
}

}  // namespace tubemesh::job
