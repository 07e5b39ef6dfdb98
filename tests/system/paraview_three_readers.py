"""What the ParaView checks share (paraview_check_xdmf.py, paraview_check_run.py): the GUI
offers three readers for an .xmf, Xdmf3ReaderS (the one OpenDataFile picks), Xdmf3ReaderT
and the legacy "XDMF Reader", so a check runs once with each; and pvbatch may not turn an
exception into an exit code, so the script's main runs under one that does.
"""
import sys

from paraview.simple import Delete, OpenDataFile, XDMFReader, Xdmf3ReaderT


def each_reader(xmf, check, fail):
    """check(reader, legacy) with each of the three readers of xmf; legacy is True for
    the old "XDMF Reader". fail(msg) when OpenDataFile cannot open it or picks another
    reader than an Xdmf3 one."""
    reader = OpenDataFile(xmf)
    if reader is None:
        fail("ParaView cannot open %s" % xmf)
    else:
        if not reader.GetXMLName().startswith("Xdmf3"):
            fail("OpenDataFile picked %s, expected an Xdmf3 reader" % reader.GetXMLName())
        check(reader, False)
        Delete(reader)
    reader = Xdmf3ReaderT(FileName=[xmf])
    check(reader, False)
    Delete(reader)
    check(XDMFReader(FileNames=[xmf]), True)


def run(name, main):
    """sys.exit(main()), an exception counting as a failure of script name."""
    try:
        code = main()
    except Exception as e:
        print("%s: FAIL: %s: %s" % (name, type(e).__name__, e), file=sys.stderr)
        code = 1
    sys.exit(code)
