// The layout networks' ONNX files (assets/models/layout_net.onnx, the whole photo;
// layout_zoom_net.onnx, the far wall's neighbourhood), built into the program so that
// detection needs no file beside it. PW_LAYOUT_NET_ONNX and PW_LAYOUT_ZOOM_NET_ONNX are
// their paths, given by CMake (which rebuilds this file when they change).
__asm__(".section .rodata\n"
        ".global pw_layout_net_onnx_begin\n"
        ".global pw_layout_net_onnx_end\n"
        ".global pw_layout_zoom_net_onnx_begin\n"
        ".global pw_layout_zoom_net_onnx_end\n"
        ".balign 16\n"
        "pw_layout_net_onnx_begin:\n"
        ".incbin \"" PW_LAYOUT_NET_ONNX "\"\n"
        "pw_layout_net_onnx_end:\n"
        ".balign 16\n"
        "pw_layout_zoom_net_onnx_begin:\n"
        ".incbin \"" PW_LAYOUT_ZOOM_NET_ONNX "\"\n"
        "pw_layout_zoom_net_onnx_end:\n"
        ".previous\n");
