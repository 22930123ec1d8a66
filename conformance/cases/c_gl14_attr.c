/* c_gl14_attr.c - the GL 1.4 vertex attributes: the secondary colour
 * (glSecondaryColor*, GL_COLOR_SUM, glSecondaryColorPointer) unlit, lit
 * with a single colour and with separate specular, two-sided, textured and
 * fogged; the fog coordinate (glFogCoord*, GL_FOG_COORD_SRC,
 * glFogCoordPointer) against the fragment depth, negative and constant,
 * in every fog mode; both in immediate mode, arrays, glArrayElement and
 * display lists, with their queries, errors and attribute stacks. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* ---- shared scenes ---- */

/* A smooth triangle pair and a fan over a 48x48 buffer (window
 * coordinates), each vertex its own primary and secondary colour. */
static const float sc_pos[9][2] = {
    { 2, 2 }, { 46, 4 }, { 6, 30 }, { 46, 4 }, { 44, 40 }, { 6, 30 },
    { 10, 44 }, { 30, 46 }, { 20, 32 },
};
static const float sc_col[9][3] = {
    { 0.2f, 0.1f, 0.6f }, { 0.7f, 0.2f, 0.1f }, { 0.1f, 0.5f, 0.2f },
    { 0.7f, 0.2f, 0.1f }, { 0.3f, 0.3f, 0.3f }, { 0.1f, 0.5f, 0.2f },
    { 0.9f, 0.9f, 0.1f }, { 0.0f, 0.2f, 0.8f }, { 0.5f, 0.0f, 0.5f },
};
static const float sc_sec[9][3] = {
    { 0.6f, 0.0f, 0.1f }, { 0.05f, 0.7f, 0.3f }, { 0.4f, 0.4f, 0.9f },
    { 0.05f, 0.7f, 0.3f }, { 0.8f, 0.1f, 0.6f }, { 0.4f, 0.4f, 0.9f },
    { 0.3f, 0.25f, 0.0f }, { 0.9f, 0.9f, 0.9f }, { 0.0f, 0.6f, 0.2f },
};

static void sc_draw_immediate(void)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 9; i++) {
        glColor3fv(sc_col[i]);
        glSecondaryColor3fv(sc_sec[i]);
        glVertex2fv(sc_pos[i]);
    }
    glEnd();
}

/* Frames: GL_COLOR_SUM on (smooth), on (flat), off. */
static void seccolor_unlit(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    for (int f = 0; f < 3; f++) {
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        if (f == 2)
            glDisable(GL_COLOR_SUM);
        fcu_clear(0.05f, 0.05f, 0.1f, 1, 1);
        sc_draw_immediate();
        fc_capture(h);
    }
}

/* The secondary colour set once, outside glBegin/glEnd (the fragment
 * program reads the current value), in and out of [0, 1]; then only some
 * vertices of a primitive carry one (the vertex format grows mid-draw). */
static void seccolor_current(fc_h *h)
{
    static const float vals[3][3] = {
        { 0.25f, 0.5f, 0.125f }, { 1.5f, -0.5f, 0.3f }, { -2.0f, 0.9f, 3.0f },
    };
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    for (int f = 0; f < 3; f++) {
        fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
        glSecondaryColor3fv(vals[f]);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 9; i++) {
            glColor3fv(sc_col[i]);
            glVertex2fv(sc_pos[i]);
        }
        glEnd();
        fc_capture(h);
    }
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glSecondaryColor3f(0.0f, 0.0f, 0.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 9; i++) {
        if (i == 4)
            glSecondaryColor3f(0.5f, 0.2f, 0.7f);
        glColor3fv(sc_col[i]);
        glVertex2fv(sc_pos[i]);
    }
    glEnd();
    fc_capture(h);
}

/* Every type of glSecondaryColor3 and its vector form: each draws a cell
 * and records the current value. */
static void seccolor_types(fc_h *h)
{
    static const GLbyte b[3] = { 100, -20, 127 };
    static const GLubyte ub[3] = { 200, 17, 255 };
    static const GLshort s[3] = { 20000, -300, 32767 };
    static const GLushort us[3] = { 50000, 1000, 65535 };
    static const GLint i[3] = { 1500000000, -7, 2147483647 };
    static const GLuint ui[3] = { 3000000000u, 12345u, 4294967295u };
    static const GLdouble d[3] = { 0.3, 0.6, 0.1 };
    static const GLfloat fl[3] = { 0.45f, 0.15f, 0.05f };
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    fcu_clear(0, 0, 0, 1, 1);
    glColor3f(0.1f, 0.1f, 0.1f);
    for (int k = 0; k < 16; k++) {
        switch (k) {
        case 0: glSecondaryColor3b(b[0], b[1], b[2]); break;
        case 1: glSecondaryColor3bv(b); break;
        case 2: glSecondaryColor3ub(ub[0], ub[1], ub[2]); break;
        case 3: glSecondaryColor3ubv(ub); break;
        case 4: glSecondaryColor3s(s[0], s[1], s[2]); break;
        case 5: glSecondaryColor3sv(s); break;
        case 6: glSecondaryColor3us(us[0], us[1], us[2]); break;
        case 7: glSecondaryColor3usv(us); break;
        case 8: glSecondaryColor3i(i[0], i[1], i[2]); break;
        case 9: glSecondaryColor3iv(i); break;
        case 10: glSecondaryColor3ui(ui[0], ui[1], ui[2]); break;
        case 11: glSecondaryColor3uiv(ui); break;
        case 12: glSecondaryColor3d(d[0], d[1], d[2]); break;
        case 13: glSecondaryColor3dv(d); break;
        case 14: glSecondaryColor3fEXT(fl[0], fl[1], fl[2]); break;
        default: glSecondaryColor3ubvEXT(ub); break;
        }
        char label[48];
        snprintf(label, sizeof label, "secondary colour %d", k);
        fc_get_float(h, label, GL_CURRENT_SECONDARY_COLOR, 4);
        fc_get_integer(h, label, GL_CURRENT_SECONDARY_COLOR, 4);
        const float x = (float)(k % 4) * 12.0f, y = (float)(k / 4) * 12.0f;
        fcu_rect(x + 1, y + 1, x + 11, y + 11, 0);
    }
    fc_error(h, "types");
    fc_capture(h);
}

/* Lighting: a single colour with GL_COLOR_SUM (the vertex program writes
 * no secondary colour), separate specular with and without GL_COLOR_SUM,
 * two-sided, flat; the current secondary colour is ignored when lit. */
static void seccolor_lit(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_ortho(-1.2, 1.2, -1.2, 1.2, -2, 2);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat pos[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    const GLfloat spec[4] = { 0.9f, 0.8f, 0.7f, 1.0f };
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.0f);
    glSecondaryColor3f(0.7f, 0.1f, 0.9f);
    for (int f = 0; f < 6; f++) {
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                      f == 0 || f == 3 ? GL_SINGLE_COLOR : GL_SEPARATE_SPECULAR_COLOR);
        if (f == 2)
            glDisable(GL_COLOR_SUM);
        else
            glEnable(GL_COLOR_SUM);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, f >= 3);
        glShadeModel(f == 5 ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0.05f, 0.05f, 0.05f, 1, 1);
        glBegin(GL_TRIANGLE_STRIP);
        for (int k = 0; k < 8; k++) {
            const float x = -1.0f + 0.28f * (float)k, y = (k & 1) ? 0.9f : -0.9f;
            glNormal3f(0.4f * x, 0.3f * y, 0.8f);
            glSecondaryColor3f(0.1f * (float)k, 0.5f, 0.2f);
            /* frames 3 and 4: the strip's second half faces back */
            glVertex3f(f >= 3 && k >= 4 ? -x + 0.6f : x, y, 0.0f);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Colour sum with a texture (the sum follows the texture environment)
 * and with fog (fog follows the sum). */
static void seccolor_tex_fog(fc_h *h)
{
    static GLubyte tex[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        tex[4 * i + 0] = (GLubyte)((i & 1) ? 255 : 40);
        tex[4 * i + 1] = (GLubyte)(i * 4);
        tex[4 * i + 2] = (GLubyte)(((i >> 3) & 1) ? 200 : 20);
        tex[4 * i + 3] = 255;
    }
    fc_pixel_ortho(h);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_COLOR_SUM);
    for (int f = 0; f < 3; f++) {
        if (f == 0 || f == 2)
            glEnable(GL_TEXTURE_2D);
        else
            glDisable(GL_TEXTURE_2D);
        if (f >= 1) {
            glEnable(GL_FOG);
            glFogi(GL_FOG_MODE, GL_LINEAR);
            glFogf(GL_FOG_START, -1.0f);
            glFogf(GL_FOG_END, 1.0f);
            const GLfloat fc[4] = { 0.2f, 0.9f, 0.4f, 1.0f };
            glFogfv(GL_FOG_COLOR, fc);
        }
        fcu_clear(0, 0, 0, 1, 1);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 9; i++) {
            glColor3fv(sc_col[i]);
            glSecondaryColor3fv(sc_sec[i]);
            glTexCoord2f(sc_pos[i][0] / 16.0f, sc_pos[i][1] / 16.0f);
            glVertex3f(sc_pos[i][0], sc_pos[i][1], 0.9f - (float)i * 0.2f);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Points, lines and a clipped triangle with the colour sum. */
static void seccolor_prims(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    fcu_clear(0, 0, 0, 1, 1);
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; i++) {
        glColor3fv(sc_col[i]);
        glSecondaryColor3fv(sc_sec[i]);
        glVertex2f(5.0f + 7.0f * (float)i, 5.0f);
    }
    glEnd();
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 6; i++) {
        glColor3fv(sc_col[i]);
        glSecondaryColor3fv(sc_sec[8 - i]);
        glVertex2f(3.0f + 8.0f * (float)i, (i & 1) ? 12.0f : 20.0f);
    }
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.2f, 0.2f); glSecondaryColor3f(0.8f, 0, 0); glVertex2f(-20, 24);
    glColor3f(0.2f, 0.6f, 0.2f); glSecondaryColor3f(0, 0.3f, 0.6f); glVertex2f(70, 30);
    glColor3f(0.0f, 0.2f, 0.5f); glSecondaryColor3f(0.5f, 0.5f, 0); glVertex2f(20, 60);
    glEnd();
    fc_capture(h);
}

/* Secondary colour arrays: float, unsigned byte, GL_BGRA, short, four
 * components; glDrawArrays, glDrawElements and glArrayElement, with the
 * primary colour array on and off. */
static void seccolor_arrays(fc_h *h)
{
    static GLfloat pos[9][2], colf[9][3], secf[9][4];
    static GLubyte secub[9][4];
    static GLshort secs[9][3];
    for (int i = 0; i < 9; i++) {
        for (int k = 0; k < 3; k++) {
            colf[i][k] = sc_col[i][k];
            secf[i][k] = sc_sec[i][k];
            secub[i][k] = (GLubyte)(sc_sec[i][k] * 255.0f);
            secs[i][k] = (GLshort)(sc_sec[i][k] * 32767.0f - 100.0f);
        }
        secf[i][3] = 0.5f;
        secub[i][3] = 77;
        pos[i][0] = sc_pos[i][0];
        pos[i][1] = sc_pos[i][1];
    }
    static const GLubyte idx[9] = { 8, 7, 6, 0, 1, 2, 3, 4, 5 };
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColor3f(0.1f, 0.2f, 0.3f);
    for (int f = 0; f < 6; f++) {
        switch (f) {
        case 0: glSecondaryColorPointer(3, GL_FLOAT, 0, secf[0]); break;   /* stride 0: packed 3 */
        case 1: glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 4, secub); break;
        case 2: glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, secub); break;
        case 3: glSecondaryColorPointer(3, GL_SHORT, 0, secs); break;
        case 4: glSecondaryColorPointer(4, GL_FLOAT, 0, secf); break;
        default: glSecondaryColorPointerEXT(3, GL_FLOAT, 16, secf); break;
        }
        if (f >= 3) {
            glEnableClientState(GL_COLOR_ARRAY);
            glColorPointer(3, GL_FLOAT, 0, colf);
        }
        fcu_clear(0, 0, 0, 1, 1);
        if (f == 1 || f == 4) {
            glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, idx);
        } else if (f == 3) {
            glBegin(GL_TRIANGLES);
            for (int i = 0; i < 9; i++)
                glArrayElement(i);
            glEnd();
        } else {
            glDrawArrays(GL_TRIANGLES, 0, 9);
        }
        fc_capture(h);
    }
    fc_get_float(h, "current after arrays", GL_CURRENT_SECONDARY_COLOR, 4);
    fc_error(h, "arrays");
}

/* Compiled into a display list: per-vertex, current, under
 * GL_COMPILE_AND_EXECUTE, and the current value after the call. */
static void seccolor_dlist(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    const GLuint l = glGenLists(2);
    glNewList(l, GL_COMPILE);
    sc_draw_immediate();
    glSecondaryColor3f(0.3f, 0.0f, 0.6f);
    glEndList();
    fc_get_float(h, "after compile", GL_CURRENT_SECONDARY_COLOR, 4);
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(l);
    fc_get_float(h, "after call", GL_CURRENT_SECONDARY_COLOR, 4);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glSecondaryColor3ub(10, 200, 40);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 9; i++) {
        glColor3fv(sc_col[i]);
        glVertex2fv(sc_pos[i]);
    }
    glEnd();
    glEndList();
    fc_capture(h);
    glSecondaryColor3f(0, 0, 0);
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(l + 1);
    fc_capture(h);
    glDeleteLists(l, 2);
}

/* Enables, queries and pointer errors. */
static void seccolor_api(fc_h *h)
{
    static GLfloat buf[16];
    fc_is_enabled(h, "COLOR_SUM default", GL_COLOR_SUM);
    fc_get_boolean(h, "COLOR_SUM default", GL_COLOR_SUM, 1);
    fc_get_float(h, "secondary default", GL_CURRENT_SECONDARY_COLOR, 4);
    glEnable(GL_COLOR_SUM);
    fc_error(h, "enable");
    fc_is_enabled(h, "COLOR_SUM on", GL_COLOR_SUM);
    fc_get_integer(h, "COLOR_SUM on", GL_COLOR_SUM, 1);
    fc_is_enabled(h, "array default", GL_SECONDARY_COLOR_ARRAY);
    static const struct { GLint size; GLenum type; GLsizei stride; } calls[] = {
        { 3, GL_FLOAT, 0 }, { 4, GL_UNSIGNED_SHORT, 12 }, { 2, GL_FLOAT, 0 },
        { 5, GL_FLOAT, 0 }, { 1, GL_BYTE, 0 }, { 3, GL_INT, -4 },
        { 3, GL_BITMAP, 0 }, { 3, GL_DOUBLE, 24 }, { 3, GL_UNSIGNED_INT, 0 },
    };
    for (size_t i = 0; i < sizeof calls / sizeof calls[0]; i++) {
        char label[48];
        snprintf(label, sizeof label, "pointer %zu", i);
        glSecondaryColorPointer(calls[i].size, calls[i].type, calls[i].stride, buf + i);
        fc_error(h, label);
        fc_get_integer(h, label, GL_SECONDARY_COLOR_ARRAY_SIZE, 1);
        fc_get_integer(h, label, GL_SECONDARY_COLOR_ARRAY_TYPE, 1);
        fc_get_integer(h, label, GL_SECONDARY_COLOR_ARRAY_STRIDE, 1);
        GLvoid *p = NULL;
        glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
        fc_value(h, label, p == NULL ? -1 : (long long)((const GLfloat *)p - buf));
    }
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    fc_is_enabled(h, "array on", GL_SECONDARY_COLOR_ARRAY);
    glBegin(GL_POINTS);
    glSecondaryColorPointer(3, GL_FLOAT, 0, buf);
    glEnd();
    fc_error(h, "pointer inside begin");
    glSecondaryColor3f(0.5f, 0.25f, 2.0f);
    fc_get_float(h, "unclamped", GL_CURRENT_SECONDARY_COLOR, 4);
    fc_get_double(h, "unclamped", GL_CURRENT_SECONDARY_COLOR, 4);
    glBegin(GL_POINTS);
    glSecondaryColor3f(0.1f, 0.2f, 0.3f);
    fc_get_float(h, "inside begin", GL_CURRENT_SECONDARY_COLOR, 4);
    glEnd();
    fc_error(h, "get inside begin");
    fc_get_float(h, "after end", GL_CURRENT_SECONDARY_COLOR, 4);
}

/* glPushAttrib/glPopAttrib: GL_CURRENT_BIT keeps the secondary colour and
 * the fog coordinate; GL_ENABLE_BIT, GL_FOG_BIT and GL_ALL_ATTRIB_BITS
 * around GL_COLOR_SUM; glPushClientAttrib around the arrays. */
static void gl14_attrib(fc_h *h)
{
    static GLfloat buf[8];
    fc_pixel_ortho(h);
    glSecondaryColor3f(0.2f, 0.4f, 0.6f);
    glFogCoordf(3.5f);
    glPushAttrib(GL_CURRENT_BIT);
    glSecondaryColor3f(0.9f, 0.8f, 0.7f);
    glFogCoordf(-1.0f);
    glPopAttrib();
    fc_get_float(h, "current popped", GL_CURRENT_SECONDARY_COLOR, 4);
    fc_get_float(h, "current popped", GL_CURRENT_FOG_COORD, 1);
    static const GLbitfield masks[4] = { GL_ENABLE_BIT, GL_FOG_BIT, GL_ALL_ATTRIB_BITS,
                                         GL_LIGHTING_BIT };
    for (int m = 0; m < 4; m++) {
        char label[48];
        snprintf(label, sizeof label, "mask %d", m);
        for (int on = 0; on < 2; on++) {
            if (on)
                glEnable(GL_COLOR_SUM);
            else
                glDisable(GL_COLOR_SUM);
            glFogi(GL_FOG_COORD_SRC, on ? GL_FOG_COORD : GL_FRAGMENT_DEPTH);
            glPushAttrib(masks[m]);
            if (on)
                glDisable(GL_COLOR_SUM);
            else
                glEnable(GL_COLOR_SUM);
            glFogi(GL_FOG_COORD_SRC, on ? GL_FRAGMENT_DEPTH : GL_FOG_COORD);
            glPopAttrib();
            fc_is_enabled(h, label, GL_COLOR_SUM);
            fc_get_integer(h, label, GL_FOG_COORD_SRC, 1);
        }
    }
    glSecondaryColorPointer(3, GL_FLOAT, 0, buf);
    glFogCoordPointer(GL_FLOAT, 8, buf + 1);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, buf + 2);
    glFogCoordPointer(GL_DOUBLE, 0, buf + 3);
    glDisableClientState(GL_FOG_COORD_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glPopClientAttrib();
    fc_get_integer(h, "client popped", GL_SECONDARY_COLOR_ARRAY_SIZE, 1);
    fc_get_integer(h, "client popped", GL_SECONDARY_COLOR_ARRAY_TYPE, 1);
    fc_get_integer(h, "client popped", GL_FOG_COORD_ARRAY_TYPE, 1);
    fc_get_integer(h, "client popped", GL_FOG_COORD_ARRAY_STRIDE, 1);
    fc_is_enabled(h, "client popped", GL_FOG_COORD_ARRAY);
    fc_is_enabled(h, "client popped", GL_SECONDARY_COLOR_ARRAY);
    fc_error(h, "attrib");
    /* a drawing after the pops: the popped current values */
    glEnable(GL_COLOR_SUM);
    glDisableClientState(GL_FOG_COORD_ARRAY);
    fcu_clear(0, 0, 0, 1, 1);
    glColor3f(0.3f, 0.3f, 0.3f);
    fcu_rect(4, 4, 44, 44, 0);
    fc_capture(h);
}

/* The raster position's distance, with a secondary colour current (its
 * query, GL_CURRENT_RASTER_SECONDARY_COLOR, is GL 3.0's:
 * honesty/rasterpos_secondary_color). */
static void gl14_rasterpos(fc_h *h)
{
    fc_pixel_ortho(h);
    glSecondaryColor3f(0.3f, 1.5f, -0.25f);
    glFogCoordf(-2.5f);
    glRasterPos2f(10, 10);
    fc_get_float(h, "raster distance (depth)", GL_CURRENT_RASTER_DISTANCE, 1);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glRasterPos2f(12, 10);
    fc_get_float(h, "raster distance (fog coord)", GL_CURRENT_RASTER_DISTANCE, 1);
    glWindowPos2f(3, 4);
    fc_get_float(h, "window distance", GL_CURRENT_RASTER_DISTANCE, 1);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glRasterPos2f(12, 12);
    fc_error(h, "rasterpos");
}

/* ---- fog coordinate ---- */

/* A perspective floor; fog coordinates per vertex with GL_FOG_COORD_SRC
 * GL_FOG_COORD, frames in each mode, then the fragment depth again. */
static void fog_view(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.6, 0.6, -0.6, 0.6, 1, 30);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_FOG);
    const GLfloat col[4] = { 0.7f, 0.75f, 0.8f, 1 };
    glFogfv(GL_FOG_COLOR, col);
}

static const float fog_v[6][3] = {
    { -3, -1, -1.2f }, { 3, -1, -1.2f }, { 6, -1, -28 },
    { -3, -1, -1.2f }, { 6, -1, -28 }, { -6, 2, -20 },
};
static const float fog_fc[6] = { 0.5f, 12.0f, 25.0f, -3.0f, -18.0f, 7.25f };

static void fog_floor(int with_coords)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++) {
        glColor3f(0.2f + 0.1f * (float)i, 0.9f - 0.1f * (float)i, 0.3f);
        if (with_coords)
            glFogCoordf(fog_fc[i]);
        glVertex3fv(fog_v[i]);
    }
    glEnd();
}

static void fogcoord_modes(fc_h *h)
{
    fog_view(h);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    for (int f = 0; f < 5; f++) {
        switch (f) {
        case 0: glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 1); glFogf(GL_FOG_END, 22); break;
        case 1: glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.09f); break;
        case 2: glFogi(GL_FOG_MODE, GL_EXP2); glFogf(GL_FOG_DENSITY, 0.07f); break;
        case 3: glShadeModel(GL_FLAT); break;
        default: glShadeModel(GL_SMOOTH); glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH); break;
        }
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        fog_floor(1);
        fc_capture(h);
    }
}

/* One fog coordinate for the whole draw (current value, not in the vertex
 * format): positive, negative, zero, huge; then the coordinate given only
 * from the third vertex on. */
static void fogcoord_current(fc_h *h)
{
    static const float vals[4] = { 6.5f, -9.0f, 0.0f, 1e30f };
    fog_view(h);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0);
    glFogf(GL_FOG_END, 12);
    for (int f = 0; f < 5; f++) {
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        if (f < 4) {
            glFogCoordd(vals[f]);
            fog_floor(0);
        } else {
            glFogCoordf(0.0f);
            glBegin(GL_TRIANGLES);
            for (int i = 0; i < 6; i++) {
                glColor3f(0.2f + 0.1f * (float)i, 0.9f - 0.1f * (float)i, 0.3f);
                if (i >= 2)
                    glFogCoordfv(&fog_fc[i]);
                glVertex3fv(fog_v[i]);
            }
            glEnd();
        }
        fc_capture(h);
    }
}

/* Fog coordinate arrays (float, double, stride, glArrayElement,
 * glDrawElements) and a display list. */
static void fogcoord_arrays(fc_h *h)
{
    static GLfloat pos[6][3], fcf[6][2];
    static GLdouble fcd[6];
    for (int i = 0; i < 6; i++) {
        memcpy(pos[i], fog_v[i], sizeof pos[i]);
        fcf[i][0] = fog_fc[i] * 0.8f;
        fcf[i][1] = 99.0f;
        fcd[i] = (double)fog_fc[5 - i];
    }
    static const GLushort idx[6] = { 3, 4, 5, 0, 1, 2 };
    fog_view(h);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.12f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glColor3f(0.9f, 0.3f, 0.2f);
    for (int f = 0; f < 5; f++) {
        if (f == 0 || f == 3)
            glFogCoordPointer(GL_FLOAT, 8, fcf);
        else if (f == 1)
            glFogCoordPointerEXT(GL_DOUBLE, 0, fcd);
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        if (f == 2) {
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
        } else if (f == 3) {
            glBegin(GL_TRIANGLES);
            for (int i = 0; i < 6; i++)
                glArrayElement(i);
            glEnd();
        } else if (f == 4) {
            const GLuint l = glGenLists(1);
            glNewList(l, GL_COMPILE);
            fog_floor(1);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glEndList();
            glCallList(l);
            glDeleteLists(l, 1);
        } else {
            glDrawArrays(GL_TRIANGLES, 0, 6);
        }
        fc_capture(h);
    }
    fc_get_float(h, "current after arrays", GL_CURRENT_FOG_COORD, 1);
    fc_error(h, "arrays");
}

/* Lit geometry with the fog coordinate (the lighting's eye position is not
 * used for fog then) and the secondary colour of separate specular. */
static void fogcoord_lit(fc_h *h)
{
    fog_view(h);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat pos[4] = { 0, 2, 1, 1 };
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    const GLfloat spec[4] = { 1, 1, 1, 1 };
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 16);
    for (int f = 0; f < 2; f++) {
        glFogi(GL_FOG_COORD_SRC, f ? GL_FRAGMENT_DEPTH : GL_FOG_COORD);
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 6; i++) {
            glNormal3f(0.1f * (float)i, 1, 0.2f);
            glFogCoordf(fog_fc[i]);
            glVertex3fv(fog_v[i]);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Queries and errors of the fog coordinate calls. */
static void fogcoord_api(fc_h *h)
{
    static GLfloat buf[8];
    fc_get_float(h, "default", GL_CURRENT_FOG_COORD, 1);
    fc_get_integer(h, "source default", GL_FOG_COORD_SRC, 1);
    glFogCoordd(-7.75);
    fc_get_float(h, "double", GL_CURRENT_FOG_COORD, 1);
    fc_get_integer(h, "double", GL_CURRENT_FOG_COORD, 1);
    const GLdouble dv = 1e40;
    glFogCoorddv(&dv);
    fc_get_float(h, "double overflow", GL_CURRENT_FOG_COORD, 1);
    glFogCoordfEXT(2.5f);
    fc_get_double(h, "ext", GL_CURRENT_FOG_COORD, 1);
    static const GLenum types[6] = { GL_FLOAT, GL_DOUBLE, GL_UNSIGNED_INT, GL_INT,
                                     GL_UNSIGNED_BYTE, GL_SHORT };
    for (int i = 0; i < 6; i++) {
        char label[48];
        snprintf(label, sizeof label, "pointer type %d", i);
        glFogCoordPointer(types[i], i * 4, buf + i);
        fc_error(h, label);
        fc_get_integer(h, label, GL_FOG_COORD_ARRAY_TYPE, 1);
        fc_get_integer(h, label, GL_FOG_COORD_ARRAY_STRIDE, 1);
    }
    glFogCoordPointer(GL_FLOAT, -1, buf);
    fc_error(h, "negative stride");
    fc_get_integer(h, "negative stride", GL_FOG_COORD_ARRAY_STRIDE, 1);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    fc_get_integer(h, "source", GL_FOG_COORD_SRC, 1);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD_ARRAY);
    fc_error(h, "bad source");
    glFogf(GL_FOG_COORD_SRC, (GLfloat)GL_FRAGMENT_DEPTH);
    fc_get_integer(h, "source float", GL_FOG_COORD_SRC, 1);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    fc_is_enabled(h, "array", GL_FOG_COORD_ARRAY);
    fc_get_boolean(h, "array", GL_FOG_COORD_ARRAY, 1);
    glBegin(GL_POINTS);
    glFogCoordPointer(GL_FLOAT, 0, buf);
    glEnd();
    fc_error(h, "pointer inside begin");
}

/* Quads and a quad strip, flat and smooth, with the secondary colour a
 * varying of its own (the quad's split and the provoking vertex). */
static void seccolor_quads(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_COLOR_SUM);
    for (int f = 0; f < 2; f++) {
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0, 0, 0, 1, 1);
        glColor3f(0.2f, 0.2f, 0.2f);
        glBegin(GL_QUADS);
        for (int i = 0; i < 8; i++) {
            glSecondaryColor3fv(sc_sec[i]);
            const float x = (i & 4) ? 24.0f : 0.0f;
            static const float qx[4] = { 2, 22, 20, 3 }, qy[4] = { 3, 2, 21, 22 };
            glVertex2f(x + qx[i & 3], qy[i & 3]);
        }
        glEnd();
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i < 8; i++) {
            glColor3fv(sc_col[i]);
            glSecondaryColor3fv(sc_sec[8 - i]);
            glVertex2f(2.0f + 6.5f * (float)(i / 2), (i & 1) ? 46.0f : 26.0f);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Fog coordinates on clipped triangles (the clipper interpolates them),
 * lines and points. */
static void fogcoord_clip_prims(fc_h *h)
{
    fog_view(h);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0);
    glFogf(GL_FOG_END, 20);
    fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.3f, 0.1f); glFogCoordf(0.0f); glVertex3f(-4, -1, -0.5f);
    glColor3f(0.2f, 1, 0.1f); glFogCoordf(20.0f); glVertex3f(3, -1, -3);
    glColor3f(0.1f, 0.3f, 1); glFogCoordf(10.0f); glVertex3f(0, 3, -8);
    glEnd();
    glLineWidth(2);
    glBegin(GL_LINES);
    glColor3f(1, 1, 0); glFogCoordf(-2.0f); glVertex3f(-2, 1, -2);
    glColor3f(0, 1, 1); glFogCoordf(19.0f); glVertex3f(2, 1.5f, -2.5f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
        glColor3f(1, 1, 1);
        glFogCoordf(2.5f * (float)i);
        glVertex3f(-1.5f + 0.4f * (float)i, -0.3f, -2);
    }
    glEnd();
    fc_capture(h);
}

/* Secondary colour and fog coordinate arrays with glArrayElement inside a
 * display list, BGRA secondary colours. */
static void gl14_arrays_dlist(fc_h *h)
{
    static GLfloat pos[6][3];
    static GLubyte sec[6][4];
    static GLdouble fcd[6];
    for (int i = 0; i < 6; i++) {
        for (int k = 0; k < 3; k++)
            pos[i][k] = fog_v[i][k];
        sec[i][0] = (GLubyte)(40 * i);
        sec[i][1] = (GLubyte)(255 - 30 * i);
        sec[i][2] = (GLubyte)(i & 1 ? 200 : 10);
        sec[i][3] = 99;
        fcd[i] = fog_fc[(i + 2) % 6];
    }
    fog_view(h);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.06f);
    glEnable(GL_COLOR_SUM);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, sec);
    glFogCoordPointer(GL_DOUBLE, 0, fcd);
    glColor3f(0.3f, 0.1f, 0.1f);
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++)
        glArrayElement(i);
    glEnd();
    glEndList();
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
    glCallList(l);
    fc_capture(h);
    fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    fc_capture(h);
    glDeleteLists(l, 1);
}

/* GL_FOG_COORD as the source ignores GL_FOG_DISTANCE_MODE_NV; switching
 * the source between draws of one frame. */
static void fogcoord_distance_modes(fc_h *h)
{
    static const GLenum modes[3] = { GL_EYE_RADIAL_NV, GL_EYE_PLANE, GL_EYE_PLANE_ABSOLUTE_NV };
    fog_view(h);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.08f);
    for (int f = 0; f < 3; f++) {
        glFogi(GL_FOG_DISTANCE_MODE_NV, (GLint)modes[f]);
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
        fog_floor(1);
        glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
        glBegin(GL_TRIANGLES);
        glColor3f(0.9f, 0.9f, 0.2f); glFogCoordf(1.0f); glVertex3f(-1, 0.5f, -2);
        glColor3f(0.2f, 0.9f, 0.9f); glFogCoordf(2.0f); glVertex3f(1, 0.6f, -9);
        glColor3f(0.9f, 0.2f, 0.9f); glFogCoordf(3.0f); glVertex3f(0, 2, -4);
        glEnd();
        fc_capture(h);
    }
}

const fc_case fc_cases_gl14_attr[] = {
    FC_CASE_RGBA("gl14/seccolor_unlit", 48, 48, 3, "gl14 seccolor", seccolor_unlit),
    FC_CASE_RGBA("gl14/seccolor_current", 48, 48, 4, "gl14 seccolor", seccolor_current),
    FC_CASE_RGBA("gl14/seccolor_types", 48, 48, 1, "gl14 seccolor api", seccolor_types),
    FC_CASE_RGBA("gl14/seccolor_lit", 48, 48, 6, "gl14 seccolor lighting", seccolor_lit),
    FC_CASE_RGBA("gl14/seccolor_tex_fog", 48, 48, 3, "gl14 seccolor texture fog", seccolor_tex_fog),
    FC_CASE_RGBA("gl14/seccolor_prims", 48, 48, 1, "gl14 seccolor", seccolor_prims),
    FC_CASE_RGBA("gl14/seccolor_arrays", 48, 48, 6, "gl14 seccolor varray", seccolor_arrays),
    FC_CASE_RGBA("gl14/seccolor_dlist", 48, 48, 3, "gl14 seccolor dlist", seccolor_dlist),
    FC_CASE_RGBA("gl14/seccolor_api", 8, 8, 0, "gl14 seccolor api error", seccolor_api),
    FC_CASE_RGBA("gl14/attrib", 48, 48, 1, "gl14 seccolor fogcoord attrib", gl14_attrib),
    FC_CASE_RGBA("gl14/rasterpos", 8, 8, 0, "gl14 seccolor fogcoord rasterpos", gl14_rasterpos),
    FC_CASE_RGBA("gl14/fogcoord_modes", 48, 48, 5, "gl14 fogcoord fog", fogcoord_modes),
    FC_CASE_RGBA("gl14/fogcoord_current", 48, 48, 5, "gl14 fogcoord fog", fogcoord_current),
    FC_CASE_RGBA("gl14/fogcoord_arrays", 48, 48, 5, "gl14 fogcoord fog varray dlist", fogcoord_arrays),
    FC_CASE_RGBA("gl14/fogcoord_lit", 48, 48, 2, "gl14 fogcoord fog lighting", fogcoord_lit),
    FC_CASE_RGBA("gl14/fogcoord_api", 8, 8, 0, "gl14 fogcoord api error", fogcoord_api),
    FC_CASE_RGBA("gl14/fogcoord_distance_modes", 48, 48, 3, "gl14 fogcoord fog", fogcoord_distance_modes),
    FC_CASE_RGBA("gl14/seccolor_quads", 48, 48, 2, "gl14 seccolor", seccolor_quads),
    FC_CASE_RGBA("gl14/fogcoord_clip_prims", 48, 48, 1, "gl14 fogcoord fog clip", fogcoord_clip_prims),
    FC_CASE_RGBA("gl14/arrays_dlist", 48, 48, 2, "gl14 seccolor fogcoord varray dlist", gl14_arrays_dlist),
    { 0 },
};
