/* fc_image.h - report images of frames: display conversion of OSMesa colour
 * buffers, and amplified difference heat maps for colour and depth.
 * Output images are 8-bit RGB, top row first, row_length x height. */
#ifndef FC_IMAGE_H
#define FC_IMAGE_H

#include "fc_compare.h"

/* Display size of a frame (the whole buffer, row padding included). */
int fc_image_width(const struct fc_frame_view *f);
int fc_image_height(const struct fc_frame_view *f);

/* Colour buffer as RGB (alpha dropped), the right way up. */
void fc_image_color(const struct fc_frame_view *f, unsigned char *rgb);

/* Heat-map colour of a difference d in [1, range]: log-scaled from yellow
 * (smallest) to red and magenta (largest). */
void fc_heat_color(double d, double range, unsigned char out[3]);

/* Colour heat map of two frames with the same layout: matching pixels are
 * the oracle's luminance dimmed to a quarter, differing ones fc_heat_color
 * of their largest byte difference. */
void fc_image_heatmap(const struct fc_frame_view *oracle, const struct fc_frame_view *fixgl,
                      unsigned char *rgb);

/* Depth heat map (depth_w x depth_h, same layout required): matching
 * values are the oracle depth as dim grey, differing ones fc_heat_color of
 * the absolute difference on a 24-bit scale.  Rows bottom-up like the
 * OSMesa depth buffer, flipped for display. */
void fc_image_depth_heatmap(const struct fc_frame_view *oracle, const struct fc_frame_view *fixgl,
                            unsigned char *rgb);

#endif
