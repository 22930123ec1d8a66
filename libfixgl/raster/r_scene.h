/*
 * The scene: the primitives of a frame binned into 64x64 tiles of the
 * framebuffer, rasterized later tile by tile, on any number of threads
 * (llvmpipe's lp_scene and lp_rast in the same roles).
 *
 * The vertex stage hands the scene what it would hand the raster core
 * (r_triangle, r_line, r_point with a draw's r_state, and whole-buffer
 * clears), in submission order.  The scene sets a triangle, a line or a
 * legacy point up once, now (its edges, box and attribute planes:
 * r_triangle_box_setup, r_line_box_setup, r_point_box_setup; the
 * non-finite or huge ones and point sprites excepted), or copies the
 * vertices of the other primitives (the attribute slots the state
 * reads), keeps one copy of each distinct r_state (holding its state
 * objects, r_state_hold), and appends the command to the bin of every
 * tile of its box that its edges do not exclude.  r_scene_run_tile then
 * replays one tile's commands in order with the draw region cut to the
 * tile (a primitive set up when binned is only rasterized there:
 * r_triangle_binned, r_line_binned, r_point_binned).
 *
 * Why the result is the same bits for every thread count and every tile
 * order: a primitive's pixels depend on the primitive and the pixel alone
 * (the coverage, the planes, the per-quad level of detail are functions of
 * the vertices and of pixel positions; quads and 4x4 blocks are aligned
 * and never straddle a 64-aligned tile), the draw region only selects
 * which pixels are written, and the pixels of one tile are written by
 * one thread in submission order.  So a tile's pixels go through exactly
 * the operations, in the order, they would go through without the scene.
 *
 * Nothing here knows GL, and a tile's replay reads only the scene, the
 * state objects and the framebuffer: any thread may run it.
 */
#ifndef FGL_R_SCENE_H
#define FGL_R_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "r_bin.h"
#include "r_state.h"

#define R_TILE_SIZE 64
#define R_TILE_LOG2 6

/* Past this many bytes of commands, vertices and bins the scene asks to
 * be rasterized before it takes more (r_scene_* return false). */
#define R_SCENE_MAX_BYTES (48u << 20)

enum r_cmd_kind {
   R_CMD_TRIANGLE,
   R_CMD_LINE,
   R_CMD_POINT,
   R_CMD_CLEAR,
   R_CMD_QUAD,
};

/* llvmpipe's linear path (ORACLE-NOTES.md "GLX linear rectangles"): a
 * tile goes the linear way when every command binned into it is a
 * rectangle or a clear; a command's `lin` says what it is.  R_LIN_NO:
 * anything else (a triangle, line or point: the tile goes the ordinary
 * way); R_LIN_SAME: a rectangle or clear drawn alike on both ways;
 * R_LIN_COLOR: a rectangle whose colour the linear way takes to other
 * bytes (its linear vertices, or the quad's linear colour).  The GL side
 * classifies; the tile decides (r_scene_run_tile). */
enum r_lin { R_LIN_NO, R_LIN_SAME, R_LIN_COLOR, R_LIN_INTERP };

/* R_LIN_INTERP: a rectangle (or a tile a triangle covers whole) whose
 * colour is a fragment-shader input, which the linear path interpolates
 * in 1.15 fixed point over the part of the tile it draws
 * (lp_linear_interp.c lp_linear_init_interp, interp_0_8): the colour's
 * planes as llvmpipe's setup makes them (premultiplied by 1/w), w_a0 the
 * 1/w plane's a0, box the rectangle's pixels [box[0], box[2]) x
 * [box[1], box[3]) (a whole tile: the tile); id: the two triangles of a
 * rectangle share one, the tile fills its box once. */
struct r_lin_interp {
   struct r_attr_plane c[4];
   float w_a0;
   int box[4];
   uint32_t id;
};
/* lp_linear_init_interp's unsigned 1.15 fixed point of f >= 0 (ORACLE-NOTES.md
 * "GLX linear bins" (5)): (unsigned)(f * 32767), at most 32767 */
static inline int16_t r_lin_ufixed_1_15(float f)
{
   const unsigned u = (unsigned)(f * 32767.0f);
   return (int16_t)(u > 32767u ? 32767u : u);
}

/* The linear path's fill of the part [x0, x1) x [y0, y1) of li's box
 * within a tile, through the fragment operations of rs (its blending
 * off): false when the path refuses it (a value over the part outside
 * [0, 1]: the ordinary path then draws it). */
bool r_lin_interp_fill(const struct r_state *rs, const struct r_lin_interp *li, int x0, int y0,
                       int x1, int y1);
/* llvmpipe's setup of a triangle as given (no winding swap: rect()'s
 * corners), for R_LIN_INTERP's planes */
struct r_tri_setup;
void r_tri_setup_as_given(const struct r_state *rs, const struct r_vertex *v0,
                          const struct r_vertex *v1, const struct r_vertex *v2,
                          struct r_tri_setup *ts);

/* R_CMD_QUAD: a clear quad over the draw region of its state (r_clear_quad)
 * with depth z, its colour on the ordinary way and on the linear one */
struct r_quad_binned {
   float z;
   float color[4];
   float lcolor[4];
};

/* The scene's triangles are set up once, when they are binned (r_tri.c
 * struct r_tri_binned: the edges, the snapped box and the attribute
 * setup, none of which depends on the draw region): r_triangle_box_setup
 * is r_triangle_box (r_state.h) that, for kind 1, also writes that setup
 * into `bin` (r_tri_binned_size(rs) bytes, 16-aligned; NULL: not wanted),
 * and r_triangle_binned draws it with rs (the binning state, its draw
 * region cut to a tile): the pixels and bytes r_triangle draws with rs. */
struct r_tri_binned;
size_t r_tri_binned_size(const struct r_state *rs);
int r_triangle_box_setup(const struct r_state *rs, const struct r_vertex *v0,
                         const struct r_vertex *v1, const struct r_vertex *v2, int box[4],
                         struct r_tri_edges *edges, struct r_tri_binned *bin);
void r_triangle_binned(const struct r_state *rs, const struct r_tri_binned *bin);
/* The pixel box bx0..bx1, by0..by1 (inclusive) of a primitive cut to the
 * draw region [rx0, rx1) x [ry0, ry1) and to the buffer fb, as
 * [box[0], box[2]) x [box[1], box[3]) for the binning; false when empty. */
static inline bool r_scene_box(const struct r_fb_state *fb, int32_t rx0, int32_t ry0,
                               int32_t rx1, int32_t ry1, int32_t bx0, int32_t by0, int32_t bx1,
                               int32_t by1, int box[4])
{
   if (bx0 < rx0) bx0 = rx0;
   if (by0 < ry0) by0 = ry0;
   if (bx1 > rx1 - 1) bx1 = rx1 - 1;
   if (by1 > ry1 - 1) by1 = ry1 - 1;
   if (bx0 < 0) bx0 = 0;
   if (by0 < 0) by0 = 0;
   if (bx1 > fb->width - 1) bx1 = fb->width - 1;
   if (by1 > fb->height - 1) by1 = fb->height - 1;
   if (bx0 > bx1 || by0 > by1)
      return false;
   box[0] = bx0;
   box[1] = by0;
   box[2] = bx1 + 1;
   box[3] = by1 + 1;
   return true;
}

/* r_tri_binned's attribute part (z, w, offset, the inputs' planes and
 * flat values) written from and read back into an r_tri_setup, bit for
 * bit: the binned lines keep their setup in it too */
struct r_tri_setup;
void r_tri_binned_pack(const struct r_tri_setup *ts, struct r_tri_binned *t);
void r_tri_binned_unpack(const struct r_tri_binned *t, struct r_tri_setup *ts);

/* Lines alike (r_line.c struct r_line_binned: the snapped corners, the
 * box and the attribute setup): r_line_box_setup returns 0 when the line
 * covers no pixel of the draw region, 1 when its pixels lie in `box`
 * ([x0, x1) x [y0, y1), cut to the region) inside its two long sides
 * `edges` (r_tri_edges_miss_tile; the third edge passes every tile),
 * with its setup written into `bin` (r_line_binned_size(rs) bytes,
 * 16-aligned), and 2 when its corners are non-finite or huge (then
 * binned by its vertices and drawn by r_line).  r_line_binned draws it
 * with rs (the binning state, its draw region cut to a tile): the pixels
 * and bytes r_line draws with rs. */
struct r_line_binned;
size_t r_line_binned_size(const struct r_state *rs);
int r_line_box_setup(const struct r_state *rs, const struct r_vertex *v0,
                     const struct r_vertex *v1, int box[4], struct r_tri_edges *edges,
                     struct r_line_binned *bin);
void r_line_binned(const struct r_state *rs, const struct r_line_binned *bin);

/* Legacy points alike (r_point.c struct r_point_binned: the square and
 * the setup): r_point_box_setup returns 0 when the point covers no pixel
 * of the draw region, 1 when it covers exactly `box` (cut to the region),
 * with its setup written into `bin` (r_point_binned_size(rs) bytes,
 * 16-aligned), and 2 for a point sprite (binned by its vertex, drawn by
 * r_point); r_point_binned draws it with rs, the binning state with its
 * draw region cut to a tile. */
struct r_point_binned;
size_t r_point_binned_size(const struct r_state *rs);
int r_point_box_setup(const struct r_state *rs, const struct r_vertex *v, int box[4],
                      struct r_point_binned *bin);
void r_point_binned(const struct r_state *rs, const struct r_point_binned *bin);

struct r_cmd {
   uint8_t kind;
   /* R_CMD_CLEAR: which buffers, and the packed values (r_clear_color,
    * r_clear_depth_stencil) */
   bool clear_color, clear_depth, clear_stencil;
   uint8_t rgba[4];
   uint8_t svalue;
   uint8_t lin;                     /* enum r_lin */
   uint32_t zvalue;
   uint32_t state;                  /* index into r_scene.states */
   /* the vertices (replayed from them when there is no setup), or, for
    * an R_LIN_COLOR triangle, its vertices with the linear colour */
   const struct r_vertex *v[3];
   /* the primitive's setup made when it was binned (one of them, by
    * kind), replayed without its vertices; NULL: replayed from v[] */
   union {
      /* R_CMD_TRIANGLE set up when binned (r_triangle_box_setup), replayed
       * by r_triangle_binned without its vertices; NULL: by r_triangle */
      const struct r_tri_binned *tri;
      /* R_CMD_LINE, R_CMD_POINT (r_line_box_setup, r_point_box_setup;
       * NULL: by r_line, r_point) */
      const struct r_line_binned *line;
      const struct r_point_binned *point;
      const struct r_quad_binned *quad;   /* R_CMD_QUAD */
   };
   const struct r_lin_interp *li;   /* lin R_LIN_INTERP */
};

struct r_bin {
   uint32_t *cmd;                   /* indices into r_scene.cmds */
   uint32_t count, capacity;
};

struct r_scene_chunk;

struct r_scene {
   /* the framebuffer the commands draw into (NULL: empty scene) */
   const struct r_fb_state *fb;
   int tiles_x, tiles_y;
   struct r_bin *bins;              /* tiles_x * tiles_y */
   unsigned bins_capacity;

   struct r_cmd *cmds;
   uint32_t ncmds, cmds_capacity;

   struct r_state *states;          /* each holds its objects */
   uint32_t nstates, states_capacity;

   /* vertex storage: chunks, reused across scenes */
   struct r_scene_chunk *chunks, *chunk;
   size_t chunk_used;

   size_t bytes;                    /* what the scene holds, for the bound */
   bool stats;                      /* some state counts (r_state.stats) */
   bool lin;                        /* some command is R_LIN_COLOR */
   /* bin every line into llvmpipe's tiles (set up when binned, its box
    * and long sides: r_line_box_setup), not a short line by its vertices'
    * box with a pixel of slack: a scene whose tiles decide (enum r_lin) */
   bool exact;
};

/* Append a primitive or a clear of the whole framebuffer of rs (its
 * values packed as r_clear_color / r_clear_depth_stencil take them).
 * False, with nothing appended, when the scene must be rasterized and
 * reset first: it is full, out of memory, or draws into another
 * framebuffer (rs->fb differs); an empty scene that still says false is
 * out of memory. */
bool r_scene_triangle(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                      const struct r_vertex *v1, const struct r_vertex *v2);
bool r_scene_line(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                  const struct r_vertex *v1);
bool r_scene_point(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v);
bool r_scene_clear(struct r_scene *s, const struct r_state *rs, bool color,
                   const uint8_t rgba[4], bool depth, uint32_t zvalue, bool stencil,
                   uint8_t svalue);
/* A triangle of a scene that may take the linear path: lin, what it is
 * in every tile (R_LIN_SAME or R_LIN_COLOR for a rectangle's, R_LIN_NO
 * for others); whole, what a triangle of R_LIN_NO is in a tile it covers
 * whole (llvmpipe shades such a tile as a rectangle: lp_setup_whole_tile),
 * and opaque, whether it then drops what the tile holds; lv (R_LIN_COLOR)
 * the vertices with the linear colour.  An R_LIN_COLOR triangle that is
 * not exact (r_triangle_box_setup's kind 2) is binned as R_LIN_SAME. */
struct r_lin_tri {
   uint8_t lin, whole;
   bool opaque;
   const struct r_vertex *const *lv;
   /* lin R_LIN_INTERP: the rectangle's (copied); whole R_LIN_INTERP: the
    * triangle's own planes are taken, box and id set here */
   const struct r_lin_interp *li;
   /* a rectangle's triangle: the rectangle's setup (its planes replace
    * the triangle's), or NULL */
   const struct r_tri_setup *rect;
};
bool r_scene_triangle_lin(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                          const struct r_vertex *v1, const struct r_vertex *v2,
                          const struct r_lin_tri *lin);
/* A point alike (R_LIN_NO for a sprite: llvmpipe draws it as a
 * triangle) */
bool r_scene_point_lin(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v,
                       uint8_t lin, const struct r_vertex *lv);
/* A clear quad (r_clear_quad over the draw region of rs, whose objects
 * must be the cache's), lin R_LIN_SAME or R_LIN_COLOR with lcolor */
bool r_scene_quad(struct r_scene *s, const struct r_state *rs, float z, const float color[4],
                  uint8_t lin, const float lcolor[4]);
/* llvmpipe's bin reset (lp_setup_whole_tile): an opaque rectangle that
 * covers a whole tile drops what the tile's bin holds; box: the pixels
 * it covers, [box[0], box[2]) x [box[1], box[3]), cut to rs's draw
 * region here.  Nothing when the scene draws into another buffer. */
void r_scene_cover(struct r_scene *s, const struct r_state *rs, const int box[4]);

static inline bool r_scene_empty(const struct r_scene *s)
{
   return s->ncmds == 0;
}

static inline unsigned r_scene_tiles(const struct r_scene *s)
{
   return (unsigned)(s->tiles_x * s->tiles_y);
}

/* Writes into order[0 .. r_scene_tiles(s) - 1] the scene's tiles in the
 * order in which `lanes` threads should take them (r_pool.h's lanes):
 * lane k, ending before lane_end[k], holds the rows of tiles ty with
 * ty mod lanes = k, the same tiles every frame, so that a thread finds
 * its tiles' pixels in its core's cache and two threads rarely write
 * neighbouring tiles, whose rows share the cache lines at their ends when
 * the application's buffer is not 64-byte aligned (a checkerboard of
 * tiles made gears 12% slower on two threads); within a lane, the tiles
 * with the most commands come first, so that the last tiles taken are
 * short and no thread waits long for another at the end.  The order of
 * the tiles changes no pixel.  lanes <= R_SCENE_MAX_LANES. */
#define R_SCENE_MAX_LANES 8
void r_scene_tile_order(const struct r_scene *s, unsigned lanes, uint32_t *order,
                        unsigned *lane_end);

/* Replays tile `tile`'s commands in order; the states that count
 * (r_state.stats) count into `stats` instead. */
/* slot: the replaying thread's worker slot (< R_SAMPLE_SLOTS), whose
 * occlusion query counter the tile's draws add to */
void r_scene_run_tile(const struct r_scene *s, unsigned tile, struct r_stats *stats,
                      unsigned slot);

/* Empties the scene (releasing its states' objects), keeping its memory
 * for the next. */
void r_scene_reset(struct r_scene *s);

/* Frees everything. */
void r_scene_fini(struct r_scene *s);

/* Whole-buffer clears restricted to the rectangle [x0,x1) x [y0,y1)
 * (r_clear.c). */
void r_clear_color_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                        const uint8_t rgba[4]);
void r_clear_depth_stencil_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                                bool depth, uint32_t zvalue, bool stencil, uint8_t svalue);

#endif
