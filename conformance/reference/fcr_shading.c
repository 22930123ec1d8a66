/* fcr_shading.c - the GLSL reference of fixgl's shading extensions (see
 * fcr_shading.h).  The GLSL below transcribes include/fixgl/shading.md "The
 * equations" line by line, in the document's operation order; every
 * intermediate is `precise` so that Mesa's NIR neither reassociates nor
 * fuses it (llvmpipe lowers ffma anyway), which keeps the program as close
 * to the document's float arithmetic as GLSL allows; dot() is written out
 * (fcr_dot) because llvmpipe sums GLSL's dot() from the last component,
 * where shading.md sums x, y, z in that order.  What remains of llvmpipe's
 * own arithmetic: pow()
 * is gallivm's exp2(log2(x) * y) approximation (the one fixgl's
 * m_gallivm_pow replicates), normalize() is v * (1 / sqrt(dot(v, v))) with
 * a true division and square root, as the document writes it.
 *
 * Values the program takes from GL state (gl_LightSource, gl_LightModel,
 * gl_FrontMaterial/gl_BackMaterial, gl_NormalMatrix, gl_NormalScale) are
 * the ones Mesa stores: eye-space light positions and spot directions,
 * spotCosCutoff = cosf(cutoff) (clamped at 0).  The state that changes the
 * program's structure is read back with glGet at fcr_bind and compiled in. */
#include "fcr_shading.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The few GL types and enums used here (no GL headers: the viewer reaches
 * OSMesa only through getproc). */
typedef unsigned int fcr_enum;
typedef unsigned int fcr_uint;
typedef int fcr_int;
typedef float fcr_float;
typedef unsigned char fcr_boolean;
typedef char fcr_char;

enum {
    FCR_LIGHTING = 0x0B50,
    FCR_LIGHT0 = 0x4000,
    FCR_LIGHT_MODEL_LOCAL_VIEWER = 0x0B51,
    FCR_LIGHT_MODEL_TWO_SIDE = 0x0B52,
    FCR_LIGHT_MODEL_COLOR_CONTROL = 0x81F8,
    FCR_SEPARATE_SPECULAR_COLOR = 0x81FA,
    FCR_COLOR_MATERIAL = 0x0B57,
    FCR_COLOR_MATERIAL_FACE = 0x0B55,
    FCR_COLOR_MATERIAL_PARAMETER = 0x0B56,
    FCR_FRONT = 0x0404,
    FCR_BACK = 0x0405,
    FCR_FRONT_AND_BACK = 0x0408,
    FCR_AMBIENT = 0x1200,
    FCR_DIFFUSE = 0x1201,
    FCR_SPECULAR = 0x1202,
    FCR_EMISSION = 0x1600,
    FCR_AMBIENT_AND_DIFFUSE = 0x1602,
    FCR_NORMALIZE = 0x0BA1,
    FCR_RESCALE_NORMAL = 0x803A,
    FCR_VERTEX_PROGRAM_TWO_SIDE = 0x8643,
    FCR_FRAGMENT_SHADER = 0x8B30,
    FCR_VERTEX_SHADER = 0x8B31,
    FCR_COMPILE_STATUS = 0x8B81,
    FCR_LINK_STATUS = 0x8B82,
    FCR_TEXTURE_2D = 0x0DE1,
    FCR_TEXTURE_ENV = 0x2300,
    FCR_TEXTURE_ENV_MODE = 0x2200,
    FCR_MODULATE = 0x2100,
    FCR_FOG = 0x0B60,
    FCR_FOG_MODE = 0x0B65,
    FCR_FOG_DENSITY = 0x0B62,
    FCR_FOG_START = 0x0B63,
    FCR_FOG_END = 0x0B64,
    FCR_LINEAR = 0x2601,
    FCR_EXP = 0x0800,
    FCR_EXP2 = 0x0801,
    FCR_MAX_LIGHTS = 8,
};

/* Colour material bits, as m_shade.h numbers them: front << 0, back << 4. */
enum { CM_AMBIENT = 1, CM_DIFFUSE = 2, CM_SPECULAR = 4, CM_EMISSION = 8, CM_BACK_SHIFT = 4 };

struct key {
    int per_fragment;
    unsigned lights;            /* bit i: GL_LIGHTi enabled */
    int local_viewer, two_side, separate_specular, normalize, rescale;
    unsigned color_material;
    int model[2];               /* front, back: 1 = Cook-Torrance */
    int texture;                /* GL_TEXTURE_2D on unit 0, GL_MODULATE */
    int fog;                    /* 0, or 1 GL_LINEAR, 2 GL_EXP, 3 GL_EXP2 */
};

struct program {
    struct key key;
    fcr_uint prog;
    fcr_int loc_ct[2];          /* fcr_ct[0], fcr_ct[1]: roughness, metalness, f0 */
    fcr_int loc_fog, loc_tex;
};

#define FCR_MAX_PROGRAMS 64

struct fcr {
    fcr_uint (*CreateShader)(fcr_enum);
    void (*ShaderSource)(fcr_uint, fcr_int, const fcr_char *const *, const fcr_int *);
    void (*CompileShader)(fcr_uint);
    void (*GetShaderiv)(fcr_uint, fcr_enum, fcr_int *);
    void (*GetShaderInfoLog)(fcr_uint, fcr_int, fcr_int *, fcr_char *);
    fcr_uint (*CreateProgram)(void);
    void (*AttachShader)(fcr_uint, fcr_uint);
    void (*LinkProgram)(fcr_uint);
    void (*GetProgramiv)(fcr_uint, fcr_enum, fcr_int *);
    void (*GetProgramInfoLog)(fcr_uint, fcr_int, fcr_int *, fcr_char *);
    void (*UseProgram)(fcr_uint);
    void (*DeleteShader)(fcr_uint);
    void (*DeleteProgram)(fcr_uint);
    fcr_int (*GetUniformLocation)(fcr_uint, const fcr_char *);
    void (*Uniform3f)(fcr_int, fcr_float, fcr_float, fcr_float);
    void (*Uniform4f)(fcr_int, fcr_float, fcr_float, fcr_float, fcr_float);
    void (*Uniform1i)(fcr_int, fcr_int);
    void (*GetFloatv)(fcr_enum, fcr_float *);
    void (*GetTexEnviv)(fcr_enum, fcr_enum, fcr_int *);
    void (*GetIntegerv)(fcr_enum, fcr_int *);
    fcr_boolean (*IsEnabled)(fcr_enum);
    void (*Enable)(fcr_enum);
    void (*Disable)(fcr_enum);

    struct program programs[FCR_MAX_PROGRAMS];
    int nprograms;
};

/* ---- GLSL -------------------------------------------------------------- */

/* The lighting of one point, shading.md "The equations".  NUM_LIGHTS,
 * LIGHT_INDEX, LOCAL_VIEWER, SEPARATE_SPECULAR, CM and MODEL_FRONT/BACK are
 * defined before it (fcr_bind). */
static const char shade_glsl[] =
    "const float PI = 3.14159265;\n"
    "uniform vec3 fcr_ct[2];   /* roughness, metalness, f0 of front, back */\n"
    "\n"
    "float spow(float x, float e)\n"
    "{\n"
    "   return e == 0.0 ? 1.0 : (x <= 0.0 ? 0.0 : pow(x, e));\n"
    "}\n"
    "\n"
    "/* dot(a,b) = a.x*b.x + a.y*b.y + a.z*b.z, summed in that order (GLSL's\n"
    " * dot() sums from the last component on llvmpipe) */\n"
    "float fcr_dot(vec3 a, vec3 b)\n"
    "{\n"
    "   precise float x = a.x * b.x;\n"
    "   precise float y = a.y * b.y;\n"
    "   precise float z = a.z * b.z;\n"
    "   precise float d = (x + y) + z;\n"
    "   return d;\n"
    "}\n"
    "\n"
    "/* normalize(v) = v * (1/sqrt(dot(v,v))) */\n"
    "vec3 fcr_normalize(vec3 v)\n"
    "{\n"
    "   precise float d = fcr_dot(v, v);\n"
    "   precise float s = 1.0 / sqrt(d);\n"
    "   precise vec3 r = v * s;\n"
    "   return r;\n"
    "}\n"
    "\n"
    "/* n: eye-space normal, P: eye position, back: the back face (two-sided\n"
    " * lighting), color: the vertex colour (colour material) */\n"
    "void shade(vec3 n, vec3 P, bool back, vec4 color, out vec4 primary, out vec4 secondary)\n"
    "{\n"
    "   int f = back ? 1 : 0;\n"
    "   int cm = back ? (CM >> 4) : CM;\n"
    "   vec4 a_m = back ? gl_BackMaterial.ambient : gl_FrontMaterial.ambient;\n"
    "   vec4 d_m = back ? gl_BackMaterial.diffuse : gl_FrontMaterial.diffuse;\n"
    "   vec4 s_m = back ? gl_BackMaterial.specular : gl_FrontMaterial.specular;\n"
    "   vec4 e_m = back ? gl_BackMaterial.emission : gl_FrontMaterial.emission;\n"
    "   float shin = back ? gl_BackMaterial.shininess : gl_FrontMaterial.shininess;\n"
    "   bool ct = back ? MODEL_BACK != 0 : MODEL_FRONT != 0;\n"
    "   if ((cm & 1) != 0) a_m = color;\n"
    "   if ((cm & 2) != 0) d_m = color;\n"
    "   if ((cm & 4) != 0) s_m = color;\n"
    "   if ((cm & 8) != 0) e_m = color;\n"
    "\n"
    "   precise vec3 N = fcr_normalize(n);\n"
    "   if (back)\n"
    "      N = -N;\n"
    "#if LOCAL_VIEWER\n"
    "   precise vec3 V = fcr_normalize(-P);\n"
    "#else\n"
    "   precise vec3 V = vec3(0.0, 0.0, 1.0);\n"
    "#endif\n"
    "   precise vec3 sum = e_m.rgb + a_m.rgb * gl_LightModel.ambient.rgb;\n"
    "   precise vec3 spec_sum = vec3(0.0);\n"
    "\n"
    "   /* Cook-Torrance constants of the face */\n"
    "   precise float rough = max(fcr_ct[f].x, 1.0 / 32.0);\n"
    "   precise float alpha = rough * rough;\n"
    "   precise float a2 = alpha * alpha;\n"
    "   precise float m = fcr_ct[f].y;\n"
    "   precise vec3 c = d_m.rgb;\n"
    "   precise vec3 F0 = vec3(fcr_ct[f].z * (1.0 - m)) + c * m;\n"
    "   precise float k = (rough + 1.0) * (rough + 1.0) / 8.0;\n"
    "\n";

/* The rest of shade(): the sum over the enabled lights. */
static const char shade_lights_glsl[] =
    "   for (int li = 0; li < NUM_LIGHTS; li++) {\n"
    "      int i = LIGHT_INDEX[li];\n"
    "      vec4 p = gl_LightSource[i].position;\n"
    "      precise vec3 L;\n"
    "      precise float att;\n"
    "      if (p.w != 0.0) {\n"
    "         L = p.xyz / p.w - P;\n"
    "         precise float d = sqrt(fcr_dot(L, L));\n"
    "         L = L / d;\n"
    "         att = 1.0 / (gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation * d\n"
    "                      + gl_LightSource[i].quadraticAttenuation * d * d);\n"
    "      } else {\n"
    "         L = fcr_normalize(p.xyz);\n"
    "         att = 1.0;\n"
    "      }\n"
    "      precise float spot;\n"
    "      if (gl_LightSource[i].spotCutoff != 180.0) {\n"
    "         precise float cs = fcr_dot(-L, fcr_normalize(gl_LightSource[i].spotDirection));\n"
    "         spot = cs >= gl_LightSource[i].spotCosCutoff ? spow(cs, gl_LightSource[i].spotExponent) : 0.0;\n"
    "      } else {\n"
    "         spot = 1.0;\n"
    "      }\n"
    "      precise float ndl = fcr_dot(N, L);\n"
    "      precise vec3 H = fcr_normalize(L + V);\n"
    "      precise vec3 ambient = gl_LightSource[i].ambient.rgb * a_m.rgb;\n"
    "      precise vec3 diffuse, specular;\n"
    "      if (!ct) {\n"
    "         diffuse = max(ndl, 0.0) * (gl_LightSource[i].diffuse.rgb * d_m.rgb);\n"
    "         specular = ndl > 0.0 ? spow(max(fcr_dot(N, H), 0.0), shin) * (gl_LightSource[i].specular.rgb * s_m.rgb)\n"
    "                              : vec3(0.0);\n"
    "      } else {\n"
    "         precise float ndv = fcr_dot(N, V);\n"
    "         precise float ndh = max(fcr_dot(N, H), 0.0);\n"
    "         precise float vdh = max(fcr_dot(V, H), 0.0);\n"
    "         diffuse = ndl > 0.0 ? (1.0 - m) * ndl * (gl_LightSource[i].diffuse.rgb * c) : vec3(0.0);\n"
    "         if (ndl > 0.0 && ndv > 0.0) {\n"
    "            precise float t = ndh * ndh * (a2 - 1.0) + 1.0;\n"
    "            precise float D = a2 / (PI * t * t);\n"
    "            precise float G = (ndl / (ndl * (1.0 - k) + k)) * (ndv / (ndv * (1.0 - k) + k));\n"
    "            precise float q = 1.0 - vdh;\n"
    "            precise float q5 = (q * q) * (q * q) * q;\n"
    "            precise vec3 F = F0 + (1.0 - F0) * q5;\n"
    "            specular = F * (PI * D * G / (4.0 * ndv)) * gl_LightSource[i].specular.rgb;\n"
    "         } else {\n"
    "            specular = vec3(0.0);\n"
    "         }\n"
    "      }\n"
    "      precise float as = att * spot;\n"
    "#if SEPARATE_SPECULAR\n"
    "      sum = sum + as * (ambient + diffuse);\n"
    "      spec_sum = spec_sum + as * specular;\n"
    "#else\n"
    "      sum = sum + as * (ambient + diffuse + specular);\n"
    "#endif\n"
    "   }\n"
    "   primary = vec4(clamp(sum, 0.0, 1.0), clamp(d_m.a, 0.0, 1.0));\n"
    "   secondary = vec4(clamp(spec_sum, 0.0, 1.0), 1.0);\n"
    "}\n";

/* The eye-space normal as GL's lighting transforms it: the
 * inverse-transpose modelview, then GL_NORMALIZE or GL_RESCALE_NORMAL.
 * GLSL's own arithmetic: gl_NormalMatrix * gl_Normal is the column chain
 * (c0*x + c1*y) + c2*z, normalize() is v * (1/sqrt(dot(v,v))) with the
 * dot summed from the last component (nir_lower_alu_width.c
 * lower_reduction), as GL's fixed-function GL_NORMALIZE does on llvmpipe;
 * the eye position is the modelview's column chain. */
static const char normal_glsl[] =
    "vec3 fcr_eye_normal()\n"
    "{\n"
    "   precise vec3 n = gl_NormalMatrix * gl_Normal;\n"
    "#if NORMALIZE\n"
    "   n = normalize(n);\n"
    "#elif RESCALE\n"
    "   n = n * gl_NormalScale;\n"
    "#endif\n"
    "   return n;\n"
    "}\n";

/* Per vertex (GL_SMOOTH / GL_FLAT): the vertex stage lights both faces,
 * the rasterizer picks the face (GL_VERTEX_PROGRAM_TWO_SIDE) and
 * interpolates as glShadeModel says. */
/* What the fixed-function vertex stage passes on besides the colours: the
 * texture coordinate of unit 0 (identity texture matrix) and the fog
 * coordinate |z_eye| (ffvertex_prog.c build_fog, with the eye position of
 * the modelview's column chain, as when lighting computed it). */
static const char vs_common_glsl[] =
    "void fcr_vertex_common(vec3 P)\n"
    "{\n"
    "#if TEXTURE\n"
    "   gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "#endif\n"
    "#if FOG\n"
    "   gl_FogFragCoord = abs(P.z);\n"
    "#endif\n"
    "}\n";

/* The fixed-function fragment stage after the lit colours, transcribed
 * from Mesa's ff_fragment_shader.cpp (emit_instructions,
 * emit_fog_instructions): GL_MODULATE with the unit 0 texture
 * (textureProj, as the fixed-function lookup), the colour sum when the
 * specular colour is separate, fog with Mesa's optimised parameters
 * (fcr_fog = STATE_FOG_PARAMS_OPTIMIZED), nothing clamped before the
 * colour buffer's conversion. */
static const char fs_common_glsl[] =
    "uniform sampler2D fcr_tex;\n"
    "uniform vec4 fcr_fog;\n"
    "vec4 fcr_fragment(vec4 pri, vec4 sec)\n"
    "{\n"
    "   precise vec4 cf = pri;\n"
    "#if TEXTURE\n"
    "   cf = textureProj(fcr_tex, gl_TexCoord[0]) * cf;\n"
    "#endif\n"
    "#if SEPARATE_SPECULAR\n"
    "   cf.rgb = cf.rgb + sec.rgb;\n"
    "#endif\n"
    "#if FOG == 1\n"
    "   precise float f = gl_FogFragCoord * fcr_fog.x + fcr_fog.y;\n"
    "#elif FOG == 2\n"
    "   precise float f = exp2(-(gl_FogFragCoord * fcr_fog.z));\n"
    "#elif FOG == 3\n"
    "   precise float t = gl_FogFragCoord * fcr_fog.w;\n"
    "   precise float f = exp2(-(t * t));\n"
    "#endif\n"
    "#if FOG\n"
    "   f = clamp(f, 0.0, 1.0);\n"
    "   cf.rgb = gl_Fog.color.rgb * (1.0 - f) + cf.rgb * f;\n"
    "#endif\n"
    "   return cf;\n"
    "}\n";

static const char vs_vertex_glsl[] =
    "void main()\n"
    "{\n"
    "   gl_Position = ftransform();\n"
    "   vec3 n = fcr_eye_normal();\n"
    "   vec3 P = (gl_ModelViewMatrix * gl_Vertex).xyz;\n"
    "   fcr_vertex_common(P);\n"
    "   vec4 pri, sec;\n"
    "   shade(n, P, false, gl_Color, pri, sec);\n"
    "   gl_FrontColor = pri;\n"
    "   gl_FrontSecondaryColor = sec;\n"
    "#if TWO_SIDE\n"
    "   shade(n, P, true, gl_Color, pri, sec);\n"
    "#endif\n"
    "   gl_BackColor = pri;\n"
    "   gl_BackSecondaryColor = sec;\n"
    "}\n";

static const char fs_vertex_glsl[] =
    "void main()\n"
    "{\n"
    "   gl_FragColor = fcr_fragment(gl_Color, gl_SecondaryColor);\n"
    "}\n";

/* Per fragment (GL_PHONG_WIN): normal, eye position and vertex colour
 * interpolated perspective-correctly, the face from gl_FrontFacing. */
static const char vs_fragment_glsl[] =
    "out vec3 fcr_n;\n"
    "out vec3 fcr_p;\n"
    "out vec4 fcr_color;\n"
    "void main()\n"
    "{\n"
    "   gl_Position = ftransform();\n"
    "   fcr_n = fcr_eye_normal();\n"
    "   fcr_p = (gl_ModelViewMatrix * gl_Vertex).xyz;\n"
    "   fcr_color = gl_Color;\n"
    "   fcr_vertex_common(fcr_p);\n"
    "}\n";

static const char fs_fragment_glsl[] =
    "in vec3 fcr_n;\n"
    "in vec3 fcr_p;\n"
    "in vec4 fcr_color;\n"
    "void main()\n"
    "{\n"
    "   vec4 pri, sec;\n"
    "   shade(fcr_n, fcr_p, TWO_SIDE != 0 && !gl_FrontFacing, fcr_color, pri, sec);\n"
    "   gl_FragColor = fcr_fragment(pri, sec);\n"
    "}\n";

/* ---- program building ------------------------------------------------- */

struct fcr *fcr_create(fcr_getproc getproc)
{
    struct fcr *r = calloc(1, sizeof *r);
    int ok = 1;
    if (!r || !getproc) {
        free(r);
        return NULL;
    }
#define GET(field, name) \
    do { \
        fcr_proc p = getproc(name); \
        memcpy(&r->field, &p, sizeof p); \
        ok = ok && p != NULL; \
    } while (0)
    GET(CreateShader, "glCreateShader");
    GET(ShaderSource, "glShaderSource");
    GET(CompileShader, "glCompileShader");
    GET(GetShaderiv, "glGetShaderiv");
    GET(GetShaderInfoLog, "glGetShaderInfoLog");
    GET(CreateProgram, "glCreateProgram");
    GET(AttachShader, "glAttachShader");
    GET(LinkProgram, "glLinkProgram");
    GET(GetProgramiv, "glGetProgramiv");
    GET(GetProgramInfoLog, "glGetProgramInfoLog");
    GET(UseProgram, "glUseProgram");
    GET(DeleteShader, "glDeleteShader");
    GET(DeleteProgram, "glDeleteProgram");
    GET(GetUniformLocation, "glGetUniformLocation");
    GET(Uniform3f, "glUniform3f");
    GET(Uniform4f, "glUniform4f");
    GET(Uniform1i, "glUniform1i");
    GET(GetFloatv, "glGetFloatv");
    GET(GetTexEnviv, "glGetTexEnviv");
    GET(GetIntegerv, "glGetIntegerv");
    GET(IsEnabled, "glIsEnabled");
    GET(Enable, "glEnable");
    GET(Disable, "glDisable");
#undef GET
    if (!ok) {
        fprintf(stderr, "fcr: an OpenGL entry point is missing\n");
        free(r);
        return NULL;
    }
    return r;
}

void fcr_destroy(struct fcr *r)
{
    if (!r)
        return;
    for (int i = 0; i < r->nprograms; i++)
        r->DeleteProgram(r->programs[i].prog);
    free(r);
}

static fcr_uint compile(struct fcr *r, fcr_enum type, const char *const *src, int n)
{
    fcr_uint s = r->CreateShader(type);
    fcr_int ok = 0;
    r->ShaderSource(s, n, src, NULL);
    r->CompileShader(s);
    r->GetShaderiv(s, FCR_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        r->GetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "fcr: %s shader does not compile:\n%s\n",
                type == FCR_VERTEX_SHADER ? "vertex" : "fragment", log);
        r->DeleteShader(s);
        return 0;
    }
    return s;
}

static struct program *build(struct fcr *r, const struct key *k)
{
    char defs[1024];
    int n = 0, nl = 0;
    const char *vs[6], *fs[5];
    fcr_uint v, f, prog;
    fcr_int ok = 0;
    struct program *p;

    n += snprintf(defs + n, sizeof defs - (size_t)n, "#version 450 compatibility\n");
    for (int i = 0; i < FCR_MAX_LIGHTS; i++)
        nl += (k->lights >> i) & 1;
    n += snprintf(defs + n, sizeof defs - (size_t)n, "#define NUM_LIGHTS %d\nconst int LIGHT_INDEX[%d] = int[](",
                  nl, nl ? nl : 1);
    for (int i = 0, first = 1; i < FCR_MAX_LIGHTS; i++) {
        if ((k->lights >> i) & 1) {
            n += snprintf(defs + n, sizeof defs - (size_t)n, "%s%d", first ? "" : ", ", i);
            first = 0;
        }
    }
    n += snprintf(defs + n, sizeof defs - (size_t)n,
                  "%s);\n#define LOCAL_VIEWER %d\n#define TWO_SIDE %d\n#define SEPARATE_SPECULAR %d\n"
                  "#define NORMALIZE %d\n#define RESCALE %d\n#define CM %u\n#define MODEL_FRONT %d\n"
                  "#define MODEL_BACK %d\n#define TEXTURE %d\n#define FOG %d\n", nl ? "" : "0",
                  k->local_viewer, k->two_side, k->separate_specular, k->normalize, k->rescale,
                  k->color_material, k->model[0], k->model[1], k->texture, k->fog);
    if (n >= (int)sizeof defs)
        return NULL;
    vs[0] = fs[0] = defs;
    vs[1] = fs[1] = shade_glsl;
    vs[2] = fs[2] = shade_lights_glsl;
    vs[3] = normal_glsl;
    vs[4] = vs_common_glsl;
    vs[5] = k->per_fragment ? vs_fragment_glsl : vs_vertex_glsl;
    fs[3] = fs_common_glsl;
    fs[4] = k->per_fragment ? fs_fragment_glsl : fs_vertex_glsl;
    v = compile(r, FCR_VERTEX_SHADER, vs, 6);
    f = compile(r, FCR_FRAGMENT_SHADER, fs, 5);
    if (!v || !f) {
        if (v)
            r->DeleteShader(v);
        if (f)
            r->DeleteShader(f);
        return NULL;
    }
    prog = r->CreateProgram();
    r->AttachShader(prog, v);
    r->AttachShader(prog, f);
    r->LinkProgram(prog);
    r->DeleteShader(v);
    r->DeleteShader(f);
    r->GetProgramiv(prog, FCR_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        r->GetProgramInfoLog(prog, sizeof log, NULL, log);
        fprintf(stderr, "fcr: the program does not link:\n%s\n", log);
        r->DeleteProgram(prog);
        return NULL;
    }
    if (r->nprograms == FCR_MAX_PROGRAMS) {     /* full: replace the oldest */
        r->DeleteProgram(r->programs[0].prog);
        memmove(&r->programs[0], &r->programs[1], (FCR_MAX_PROGRAMS - 1) * sizeof r->programs[0]);
        r->nprograms--;
    }
    p = &r->programs[r->nprograms++];
    p->key = *k;
    p->prog = prog;
    p->loc_ct[0] = r->GetUniformLocation(prog, "fcr_ct[0]");
    p->loc_ct[1] = r->GetUniformLocation(prog, "fcr_ct[1]");
    p->loc_fog = r->GetUniformLocation(prog, "fcr_fog");
    p->loc_tex = r->GetUniformLocation(prog, "fcr_tex");
    return p;
}

/* GL_COLOR_MATERIAL's face and parameter as colour material bits. */
static unsigned color_material_bits(struct fcr *r)
{
    fcr_int face = 0, param = 0;
    unsigned bits = 0, out = 0;
    if (!r->IsEnabled(FCR_COLOR_MATERIAL))
        return 0;
    r->GetIntegerv(FCR_COLOR_MATERIAL_FACE, &face);
    r->GetIntegerv(FCR_COLOR_MATERIAL_PARAMETER, &param);
    switch (param) {
    case FCR_AMBIENT: bits = CM_AMBIENT; break;
    case FCR_DIFFUSE: bits = CM_DIFFUSE; break;
    case FCR_SPECULAR: bits = CM_SPECULAR; break;
    case FCR_EMISSION: bits = CM_EMISSION; break;
    case FCR_AMBIENT_AND_DIFFUSE: bits = CM_AMBIENT | CM_DIFFUSE; break;
    default: break;
    }
    if (face == FCR_FRONT || face == FCR_FRONT_AND_BACK)
        out |= bits;
    if (face == FCR_BACK || face == FCR_FRONT_AND_BACK)
        out |= bits << CM_BACK_SHIFT;
    return out;
}

int fcr_bind(struct fcr *r, int per_fragment, const struct fcr_face *front,
             const struct fcr_face *back)
{
    static const struct fcr_face blinn = { 0, 0.5f, 0.0f, 0.04f };
    const struct fcr_face *face[2] = { front ? front : &blinn, back ? back : &blinn };
    struct key k;
    struct program *p = NULL;
    fcr_int v = 0;

    if (!r->IsEnabled(FCR_LIGHTING)) {
        fcr_unbind(r);
        return 1;
    }
    memset(&k, 0, sizeof k);
    k.per_fragment = per_fragment != 0;
    for (int i = 0; i < FCR_MAX_LIGHTS; i++)
        k.lights |= (unsigned)(r->IsEnabled((fcr_enum)(FCR_LIGHT0 + i)) != 0) << i;
    r->GetIntegerv(FCR_LIGHT_MODEL_LOCAL_VIEWER, &v);
    k.local_viewer = v != 0;
    r->GetIntegerv(FCR_LIGHT_MODEL_TWO_SIDE, &v);
    k.two_side = v != 0;
    r->GetIntegerv(FCR_LIGHT_MODEL_COLOR_CONTROL, &v);
    k.separate_specular = v == FCR_SEPARATE_SPECULAR_COLOR;
    k.normalize = r->IsEnabled(FCR_NORMALIZE) != 0;
    k.rescale = r->IsEnabled(FCR_RESCALE_NORMAL) != 0;
    k.color_material = color_material_bits(r);
    k.model[0] = face[0]->cook_torrance != 0;
    k.model[1] = face[1]->cook_torrance != 0;
    if (r->IsEnabled(FCR_TEXTURE_2D)) {
        r->GetTexEnviv(FCR_TEXTURE_ENV, FCR_TEXTURE_ENV_MODE, &v);
        if (v != FCR_MODULATE) {
            fprintf(stderr, "fcr: only GL_MODULATE texturing is emulated\n");
            return 0;
        }
        k.texture = 1;
    }
    if (r->IsEnabled(FCR_FOG)) {
        r->GetIntegerv(FCR_FOG_MODE, &v);
        k.fog = v == FCR_LINEAR ? 1 : v == FCR_EXP ? 2 : 3;
    }

    for (int i = 0; i < r->nprograms && !p; i++)
        if (memcmp(&r->programs[i].key, &k, sizeof k) == 0)
            p = &r->programs[i];
    if (!p && !(p = build(r, &k)))
        return 0;
    r->UseProgram(p->prog);
    for (int f = 0; f < 2; f++)
        if (p->loc_ct[f] >= 0)
            r->Uniform3f(p->loc_ct[f], face[f]->roughness, face[f]->metalness, face[f]->f0);
    if (p->loc_tex >= 0)
        r->Uniform1i(p->loc_tex, 0);
    if (p->loc_fog >= 0) {
        /* [S: program/prog_statevars.c STATE_FOG_PARAMS_OPTIMIZED] */
        fcr_float start = 0, end = 1, density = 1;
        float val;
        r->GetFloatv(FCR_FOG_START, &start);
        r->GetFloatv(FCR_FOG_END, &end);
        r->GetFloatv(FCR_FOG_DENSITY, &density);
        val = end == start ? 1.0f : (float)(-1.0f / (end - start));
        r->Uniform4f(p->loc_fog, val, end * -val, (float)(density * 1.44269504088896340736),
                     (float)(density * 1.201122408786449815));
    }
    if (k.two_side && !k.per_fragment)
        r->Enable(FCR_VERTEX_PROGRAM_TWO_SIDE);
    else
        r->Disable(FCR_VERTEX_PROGRAM_TWO_SIDE);
    return 1;
}

void fcr_unbind(struct fcr *r)
{
    r->UseProgram(0);
    r->Disable(FCR_VERTEX_PROGRAM_TWO_SIDE);
}
