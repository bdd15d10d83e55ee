"""What both generators (gen_gl.py, gen_egl.py) need from a Khronos registry file and its
output: the error exit, the whitespace and declarator rules of the registry's <proto> and
<param> text, and writing a file only when it changed."""

import os
import re
import sys


def fail(message):
    """Stops the build with a message that names the problem (the build log shows it)."""
    sys.stderr.write('%s: error: %s\n' % (os.path.basename(sys.argv[0]), message))
    sys.exit(1)


def squash(text):
    """Collapses the registry's free-form whitespace so declarations come out uniform."""
    return re.sub(r'\s+', ' ', text).strip()


def text_without_name(elem):
    """Returns the text of a <proto> or <param>, leaving out its <name> child."""
    parts = [elem.text or '']
    for child in elem:
        if child.tag != 'name':
            parts.append(''.join(child.itertext()))
        parts.append(child.tail or '')
    return squash(''.join(parts))


def declarator(ctype, name):
    """Joins a type and a name the way C programmers write it ("const GLubyte *glGetString")."""
    return ctype + name if ctype.endswith('*') else '%s %s' % (ctype, name)


def write_if_different(path, content):
    """Leaves an unchanged file alone so that its timestamp does not trigger rebuilds."""
    try:
        with open(path, encoding='utf-8', newline='') as handle:
            if handle.read() == content:
                return
    except OSError:
        pass
    os.makedirs(os.path.dirname(path), exist_ok=True)
    temporary = path + '.tmp'
    with open(temporary, 'w', encoding='utf-8', newline='') as handle:
        handle.write(content)
    os.replace(temporary, path)
