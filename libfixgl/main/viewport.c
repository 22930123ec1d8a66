/* placeholder: filled in by the foundation work */
typedef int fgl_placeholder_main_viewport_c;
