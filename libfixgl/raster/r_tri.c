/* placeholder: filled in by the foundation work */
typedef int fgl_placeholder_raster_r_tri_c;
