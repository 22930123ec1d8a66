/* placeholder: filled in by the foundation work */
typedef int fgl_placeholder_tnl_t_render_c;
