using System;
using Microsoft.Win32.SafeHandles;

namespace Fitfeel
{
    /// <summary>
    /// Owns a fitfeel_scene*: released exactly once, by Dispose or by the finalizer, and never
    /// while a P/Invoke call is using it (the runtime counts SafeHandle arguments in flight).
    /// </summary>
    public sealed class SceneHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        // The marshaller creates the handle for the C interface's out parameter.
        private SceneHandle() : base(true)
        {
        }

        protected override bool ReleaseHandle()
        {
            NativeMethods.fitfeel_close(handle);
            return true;
        }
    }
}
