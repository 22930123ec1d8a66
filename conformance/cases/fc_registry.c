/* fc_registry.c - the table of all fixed cases, in group order. */
#include "cases.h"
#include "fc_harness.h"

static const fc_case *const groups[] = {
    fc_cases_fill, fc_cases_shade, fc_cases_clip, fc_cases_depth,
    fc_cases_format, fc_cases_viewport, fc_cases_matrix, fc_cases_query,
    fc_cases_vertex, fc_cases_readpix, fc_cases_pix_format, fc_cases_pix_format_tex,
    fc_cases_errors,
    fc_cases_robust,
    fc_cases_light, fc_cases_light_space, fc_cases_light_normal,
    fc_cases_light_mat, fc_cases_light_prim, fc_cases_light_api,
    fc_cases_fog,
    fc_cases_fragment,
    fc_cases_polygon,
    fc_cases_points_lines,
    fc_cases_polygon_mode,
    fc_cases_varray,
    fc_cases_dlist,
    fc_cases_attrib,
    fc_cases_demo,
    fc_cases_select,
    fc_cases_texstate,
    fc_cases_tex_coord,
    fc_cases_tex_image,
    fc_cases_accum,
    fc_cases_query_walk,
    fc_cases_eval,
    fc_cases_pixelstate,
    fc_cases_pix_draw,
    fc_cases_rasterpos,
    fc_cases_windowpos,
    fc_cases_tex_sample,
    fc_cases_tex_env,
    fc_cases_tex_wrap,
    fc_cases_demo_tex,
    fc_cases_shading,
    fc_cases_shading_paths,
    fc_cases_gl14_attr,
    fc_cases_gl14_ops,
    fc_cases_gl14_points,
    fc_cases_gl14_sprite,
    fc_cases_gl15,
    fc_cases_tex3d,
    fc_cases_shadow,
    fc_cases_cubemap,
    fc_cases_osmesa,
    fc_cases_tex_copy,
    fc_cases_compressed,
    fc_cases_honesty,
    fc_cases_demo_cube_shadow,
};

size_t fc_case_count(void)
{
    size_t n = 0;
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++)
        for (const fc_case *c = groups[g]; c->name; c++)
            n++;
    return n;
}

const fc_case *fc_case_at(size_t i)
{
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++)
        for (const fc_case *c = groups[g]; c->name; c++)
            if (i-- == 0)
                return c;
    return NULL;
}
