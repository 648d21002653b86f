using System;
using System.Runtime.InteropServices;
using System.Security;

namespace Fitfeel
{
    /// <summary>
    /// The C interface (fitfeel.h) as declared to the runtime. Strings go in as NUL-terminated
    /// UTF-8 bytes and come out as pointers: .NET Framework profiles (Unity's, Mono's) have no
    /// UTF-8 string marshalling of their own, and a byte[] in is marshalled the same everywhere.
    /// </summary>
    [SuppressUnmanagedCodeSecurity]  // the servo loop steps a thousand times a second
    internal static class NativeMethods
    {
        // libfitfeel_c.so on Linux: found on LD_LIBRARY_PATH, or in a Unity project's Plugins.
        internal const string Library = "fitfeel_c";

        [DllImport(Library)]
        internal static extern int fitfeel_abi_version();

        [DllImport(Library)]
        internal static extern int fitfeel_open_file(byte[] path, ulong seed, out SceneHandle scene);

        [DllImport(Library)]
        internal static extern int fitfeel_open_yaml(byte[] yaml, byte[] name, ulong seed,
                                                     out SceneHandle scene);

        [DllImport(Library)]
        internal static extern int fitfeel_step(SceneHandle scene, ref DeviceState device,
                                                out Wrench wrench);

        [DllImport(Library)]
        internal static extern int fitfeel_contact_state(SceneHandle scene, out Contact contact);

        [DllImport(Library)]
        internal static extern ulong fitfeel_ticks(SceneHandle scene);

        [DllImport(Library)]
        internal static extern int fitfeel_pressure_map(SceneHandle scene, double[] pressure,
                                                        int capacity, out int rows, out int columns);

        [DllImport(Library)]
        internal static extern int fitfeel_write_outputs(SceneHandle scene, byte[] dir);

        [DllImport(Library)]
        internal static extern IntPtr fitfeel_last_error(SceneHandle scene);

        [DllImport(Library)]
        internal static extern IntPtr fitfeel_thread_last_error();

        // IntPtr, not SceneHandle: called from the handle's release, when it is already closing.
        [DllImport(Library)]
        internal static extern void fitfeel_close(IntPtr scene);
    }
}
