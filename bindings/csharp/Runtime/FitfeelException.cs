using System;

namespace Fitfeel
{
    /// <summary>
    /// A call the C interface refused, with its status and its last error text: the binding
    /// turns every status but Ok and Done into one of these, so no refusal goes unnoticed.
    /// </summary>
    public class FitfeelException : Exception
    {
        public FitfeelException(Status status, string message) : base(message)
        {
            Status = status;
        }

        public Status Status { get; private set; }
    }
}
