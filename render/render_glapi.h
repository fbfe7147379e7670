/* render_glapi.h: the GL and OSMesa functions the renderer calls, loaded from libOSMesa at run time.
 *
 * footsim does not link OSMesa (and the LLVM it pulls in, tens of milliseconds to load): a
 * command that draws nothing never loads it. fs_render_gl_load opens the library the first time a
 * renderer is opened and fills the table `gl`; the renderer calls gl.Begin(...) for glBegin(...).
 * FOOTSIM_OSMESA in the environment names another library file to load instead. */
#ifndef FS_RENDER_GLAPI_H
#define FS_RENDER_GLAPI_H

#include "footsim/base/fs_error.h"

#include <GL/gl.h>
#include <GL/osmesa.h>

/* X(return type, member, parameters, symbol) for each function. */
#define RENDER_GL_FUNCTIONS(X)                                                                        \
    X(void, Begin, (GLenum), "glBegin")                                                               \
    X(void, End, (void), "glEnd")                                                                     \
    X(void, Enable, (GLenum), "glEnable")                                                             \
    X(void, Disable, (GLenum), "glDisable")                                                           \
    X(void, Vertex2i, (GLint, GLint), "glVertex2i")                                                   \
    X(void, Vertex3d, (GLdouble, GLdouble, GLdouble), "glVertex3d")                                   \
    X(void, Vertex3dv, (const GLdouble *), "glVertex3dv")                                             \
    X(void, Normal3d, (GLdouble, GLdouble, GLdouble), "glNormal3d")                                   \
    X(void, Normal3dv, (const GLdouble *), "glNormal3dv")                                             \
    X(void, Color3f, (GLfloat, GLfloat, GLfloat), "glColor3f")                                        \
    X(void, Color3fv, (const GLfloat *), "glColor3fv")                                                \
    X(void, Color4f, (GLfloat, GLfloat, GLfloat, GLfloat), "glColor4f")                               \
    X(void, Color3ub, (GLubyte, GLubyte, GLubyte), "glColor3ub")                                      \
    X(void, Recti, (GLint, GLint, GLint, GLint), "glRecti")                                           \
    X(void, MatrixMode, (GLenum), "glMatrixMode")                                                     \
    X(void, LoadIdentity, (void), "glLoadIdentity")                                                   \
    X(void, LoadMatrixd, (const GLdouble *), "glLoadMatrixd")                                         \
    X(void, MultMatrixd, (const GLdouble *), "glMultMatrixd")                                         \
    X(void, PushMatrix, (void), "glPushMatrix")                                                       \
    X(void, PopMatrix, (void), "glPopMatrix")                                                         \
    X(void, Scaled, (GLdouble, GLdouble, GLdouble), "glScaled")                                       \
    X(void, Translated, (GLdouble, GLdouble, GLdouble), "glTranslated")                               \
    X(void, Ortho, (GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble), "glOrtho")           \
    X(void, Viewport, (GLint, GLint, GLsizei, GLsizei), "glViewport")                                 \
    X(void, Scissor, (GLint, GLint, GLsizei, GLsizei), "glScissor")                                   \
    X(void, ClearColor, (GLclampf, GLclampf, GLclampf, GLclampf), "glClearColor")                     \
    X(void, Clear, (GLbitfield), "glClear")                                                           \
    X(void, DepthFunc, (GLenum), "glDepthFunc")                                                       \
    X(void, DepthMask, (GLboolean), "glDepthMask")                                                    \
    X(void, BlendFunc, (GLenum, GLenum), "glBlendFunc")                                               \
    X(void, PolygonOffset, (GLfloat, GLfloat), "glPolygonOffset")                                     \
    X(void, StencilFunc, (GLenum, GLint, GLuint), "glStencilFunc")                                    \
    X(void, StencilOp, (GLenum, GLenum, GLenum), "glStencilOp")                                       \
    X(void, LineWidth, (GLfloat), "glLineWidth")                                                      \
    X(void, PointSize, (GLfloat), "glPointSize")                                                      \
    X(void, Lightfv, (GLenum, GLenum, const GLfloat *), "glLightfv")                                  \
    X(void, LightModelfv, (GLenum, const GLfloat *), "glLightModelfv")                                \
    X(void, ColorMaterial, (GLenum, GLenum), "glColorMaterial")                                       \
    X(void, ShadeModel, (GLenum), "glShadeModel")                                                     \
    X(GLuint, GenLists, (GLsizei), "glGenLists")                                                      \
    X(void, NewList, (GLuint, GLenum), "glNewList")                                                   \
    X(void, EndList, (void), "glEndList")                                                             \
    X(void, CallList, (GLuint), "glCallList")                                                         \
    X(void, Finish, (void), "glFinish")                                                               \
    X(OSMesaContext, CreateContextExt, (GLenum, GLint, GLint, GLint, OSMesaContext),                  \
      "OSMesaCreateContextExt")                                                                       \
    X(GLboolean, MakeCurrent, (OSMesaContext, void *, GLenum, GLsizei, GLsizei), "OSMesaMakeCurrent") \
    X(void, DestroyContext, (OSMesaContext), "OSMesaDestroyContext")                                  \
    X(OSMesaContext, GetCurrentContext, (void), "OSMesaGetCurrentContext")

typedef struct render_gl_api {
#define RENDER_GL_MEMBER(ret, member, params, symbol) ret(GLAPIENTRY *member) params;
    RENDER_GL_FUNCTIONS(RENDER_GL_MEMBER)
#undef RENDER_GL_MEMBER
} render_gl_api;

/* The table (fs_render_gl; `gl` for short in the renderer's own files). */
extern render_gl_api fs_render_gl;
#define gl fs_render_gl

/* Loads libOSMesa and fills gl (once; later calls return at once). FS_BAD_INPUT, saying what to
 * install, when it is not there or lacks a function. */
fs_status fs_render_gl_load(fs_error *err);

#endif
