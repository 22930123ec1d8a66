/* placeholder: filled in by the foundation work */
typedef int fgl_placeholder_raster_r_clear_c;
