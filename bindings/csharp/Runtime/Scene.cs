using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Fitfeel
{
    /// <summary>
    /// A scene loaded, prepared and ready to step (fitfeel_scene): the same ticks as `fitfeel run`
    /// for the same device states. Every refusal of the C interface is thrown as a
    /// FitfeelException (ScenarioException for a scenario) with the C interface's text.
    /// Threads: as docs/embedding.md's table for the C calls; Step and ContactState from one
    /// thread at a time.
    /// </summary>
    public sealed class Scene : IDisposable
    {
        /// <summary>The C interface's version this binding is declared against.</summary>
        public const int AbiVersion = 2;

        readonly SceneHandle handle;

        Scene(SceneHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>fitfeel_open_file: seed 0 keeps the scene's run.seed.</summary>
        public static Scene OpenFile(string path, ulong seed = 0)
        {
            if (path == null) throw new ArgumentNullException("path");
            CheckAbi();
            SceneHandle h;
            int status = NativeMethods.fitfeel_open_file(Utf8(path), seed, out h);
            return Opened(status, h);
        }

        /// <summary>fitfeel_open_yaml: `name` is what error messages call the text.</summary>
        public static Scene OpenYaml(string yaml, string name, ulong seed = 0)
        {
            if (yaml == null) throw new ArgumentNullException("yaml");
            CheckAbi();
            SceneHandle h;
            int status = NativeMethods.fitfeel_open_yaml(Utf8(yaml), Utf8(name ?? "<yaml>"), seed,
                                                         out h);
            return Opened(status, h);
        }

        /// <summary>
        /// fitfeel_step: one tick. True with the wrench to render; false (and a zero wrench) once
        /// the scene's run.duration is done. Allocates nothing.
        /// </summary>
        public bool Step(ref DeviceState device, out Wrench wrench)
        {
            int status = NativeMethods.fitfeel_step(handle, ref device, out wrench);
            if (status == (int)Status.Ok) return true;
            if (status == (int)Status.Done) return false;
            throw Refused(status, "fitfeel_step refused the call");
        }

        /// <summary>fitfeel_contact_state: the contact at the last step.</summary>
        public Contact ContactState()
        {
            Contact c;
            int status = NativeMethods.fitfeel_contact_state(handle, out c);
            if (status != (int)Status.Ok) throw Refused(status, "fitfeel_contact_state refused the call");
            return c;
        }

        /// <summary>fitfeel_ticks: ticks done so far.</summary>
        public ulong Ticks
        {
            get { return NativeMethods.fitfeel_ticks(handle); }
        }

        /// <summary>
        /// fitfeel_pressure_map: Pa per cell of the inner part's grid at the last step's pose,
        /// row-major. Allocates: not from the servo loop.
        /// </summary>
        public double[] PressureMap(out int rows, out int columns)
        {
            NativeMethods.fitfeel_pressure_map(handle, null, 0, out rows, out columns);
            var pressure = new double[rows * columns];
            int status = NativeMethods.fitfeel_pressure_map(handle, pressure, pressure.Length,
                                                            out rows, out columns);
            if (status != (int)Status.Ok) throw Refused(status, LastError());
            return pressure;
        }

        /// <summary>fitfeel_write_outputs: DIR/trace.csv and DIR/summary.json of the ticks so far.</summary>
        public void WriteOutputs(string dir)
        {
            if (dir == null) throw new ArgumentNullException("dir");
            int status = NativeMethods.fitfeel_write_outputs(handle, Utf8(dir));
            if (status != (int)Status.Ok) throw Refused(status, LastError());
        }

        /// <summary>fitfeel_close, once; the handle's finalizer does it for a scene not disposed.</summary>
        public void Dispose()
        {
            handle.Dispose();
        }

        static void CheckAbi()
        {
            int abi = NativeMethods.fitfeel_abi_version();
            if (abi != AbiVersion)
            {
                throw new FitfeelException(Status.Error, "libfitfeel_c has C ABI " + abi +
                                                         ", this binding is declared against " + AbiVersion);
            }
        }

        static Scene Opened(int status, SceneHandle h)
        {
            if (status == (int)Status.Ok) return new Scene(h);
            if (h != null) h.Dispose();
            throw Refused(status, Text(NativeMethods.fitfeel_thread_last_error()));
        }

        string LastError()
        {
            return Text(NativeMethods.fitfeel_last_error(handle));
        }

        static FitfeelException Refused(int status, string text)
        {
            if (status == (int)Status.ScenarioError) return new ScenarioException(text);
            return new FitfeelException((Status)status, text);
        }

        static byte[] Utf8(string s)
        {
            var bytes = new byte[Encoding.UTF8.GetByteCount(s) + 1];
            Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        static string Text(IntPtr p)
        {
            if (p == IntPtr.Zero) return "";
            int n = 0;
            while (Marshal.ReadByte(p, n) != 0) ++n;
            var bytes = new byte[n];
            Marshal.Copy(p, bytes, 0, n);
            return Encoding.UTF8.GetString(bytes);
        }
    }
}
