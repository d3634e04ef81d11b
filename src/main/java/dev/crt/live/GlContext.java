package dev.crt.live;

import java.nio.IntBuffer;
import org.lwjgl.PointerBuffer;
import org.lwjgl.egl.EGL;
import org.lwjgl.egl.EGL10;
import org.lwjgl.egl.EGL12;
import org.lwjgl.egl.EGL14;
import org.lwjgl.egl.EGL15;
import org.lwjgl.egl.EGLCapabilities;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GL11;
import org.lwjgl.system.JNI;
import org.lwjgl.system.MemoryStack;

/**
 * A headless OpenGL 3.3 core context made through EGL on Mesa's surfaceless platform: no X
 * server, no window; everything is drawn into framebuffer objects. The context is current on the
 * thread that created it, and only there.
 */
public final class GlContext implements AutoCloseable {
    private static final int EGL_PLATFORM_SURFACELESS_MESA = 0x31DD;

    private final long display;
    private final long context;
    private final String description;
    private boolean closed;

    private GlContext(long display, long context, String description) {
        this.display = display;
        this.context = context;
        this.description = description;
    }

    /** Makes a context and makes it current on this thread, or says in one sentence why it cannot. */
    public static GlContext create() throws GlUnavailableException {
        // GL functions come from eglGetProcAddress, so libGL and libGLX (X11) are never loaded.
        System.setProperty("org.lwjgl.opengl.explicitInit", "true");
        EGLCapabilities egl;
        try {
            // EGL's class initialiser loads libEGL unless told otherwise; a failure shows up here.
            egl = EGL.getCapabilities();
        } catch (Throwable e) {
            throw new GlUnavailableException("OpenGL is not available: the EGL library (libEGL.so.1, Debian package"
                    + " libegl1) could not be loaded (" + e.getMessage() + ")", e);
        }
        // LWJGL's eglGetPlatformDisplay wrapper rejects a null native display, which the
        // surfaceless platform requires: call the entry point directly.
        long getPlatformDisplay = egl.eglGetPlatformDisplay != 0 ? egl.eglGetPlatformDisplay : egl.eglGetPlatformDisplayEXT;
        if (getPlatformDisplay == 0) {
            throw new GlUnavailableException("OpenGL is not available: this EGL library has no eglGetPlatformDisplay");
        }
        long display = JNI.invokePPP(EGL_PLATFORM_SURFACELESS_MESA, 0L, 0L, getPlatformDisplay);
        if (display == EGL10.EGL_NO_DISPLAY) {
            throw new GlUnavailableException("OpenGL is not available: EGL has no surfaceless display"
                    + " (is Mesa's libgl1-mesa-dri installed?)");
        }
        long context;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer major = stack.mallocInt(1), minor = stack.mallocInt(1);
            if (!EGL10.eglInitialize(display, major, minor)) {
                throw new GlUnavailableException("OpenGL is not available: EGL could not be initialised (error 0x"
                        + Integer.toHexString(EGL10.eglGetError()) + "; is libgl1-mesa-dri installed?)");
            }
            if (!EGL14.eglBindAPI(EGL14.EGL_OPENGL_API)) {
                EGL10.eglTerminate(display);
                throw new GlUnavailableException("OpenGL is not available: EGL offers no desktop OpenGL here");
            }
            IntBuffer configAttributes = stack.ints(
                    EGL10.EGL_SURFACE_TYPE, EGL10.EGL_PBUFFER_BIT,
                    EGL12.EGL_RENDERABLE_TYPE, EGL15.EGL_OPENGL_BIT,
                    EGL10.EGL_NONE);
            PointerBuffer configs = stack.mallocPointer(1);
            IntBuffer count = stack.mallocInt(1);
            if (!EGL10.eglChooseConfig(display, configAttributes, configs, count) || count.get(0) == 0) {
                EGL10.eglTerminate(display);
                throw new GlUnavailableException("OpenGL is not available: EGL has no configuration for desktop OpenGL");
            }
            IntBuffer contextAttributes = stack.ints(
                    EGL15.EGL_CONTEXT_MAJOR_VERSION, 3,
                    EGL15.EGL_CONTEXT_MINOR_VERSION, 3,
                    EGL15.EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL15.EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                    EGL10.EGL_NONE);
            context = EGL10.eglCreateContext(display, configs.get(0), EGL10.EGL_NO_CONTEXT, contextAttributes);
            if (context == EGL10.EGL_NO_CONTEXT) {
                int error = EGL10.eglGetError();
                EGL10.eglTerminate(display);
                throw new GlUnavailableException("OpenGL is not available: EGL could not make an OpenGL 3.3 core context"
                        + " (error 0x" + Integer.toHexString(error) + ")");
            }
            if (!EGL10.eglMakeCurrent(display, EGL10.EGL_NO_SURFACE, EGL10.EGL_NO_SURFACE, context)) {
                EGL10.eglDestroyContext(display, context);
                EGL10.eglTerminate(display);
                throw new GlUnavailableException("OpenGL is not available: the surfaceless OpenGL context could not be"
                        + " made current");
            }
        }
        loadGl();
        GL.createCapabilities();
        String description = GL11.glGetString(GL11.GL_VERSION) + " on " + GL11.glGetString(GL11.GL_RENDERER);
        return new GlContext(display, context, description);
    }

    private static synchronized void loadGl() {
        if (glLoaded) return;
        GL.create(name -> EGL10.eglGetProcAddress(name));
        glLoaded = true;
    }

    private static boolean glLoaded;

    /** The GL version and renderer, e.g. "4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits)". */
    public String description() { return description; }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        EGL10.eglMakeCurrent(display, EGL10.EGL_NO_SURFACE, EGL10.EGL_NO_SURFACE, EGL10.EGL_NO_CONTEXT);
        EGL10.eglDestroyContext(display, context);
        GL.setCapabilities(null);
    }
}
