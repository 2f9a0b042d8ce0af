#pragma once

// Visits every expression and every variable declaration of a compilation unit, for the scans
// that must see the whole program before code is emitted (the process image's size, the library
// blocks a project names).
#include "interpreter/compiler/ast.h"

namespace iec::interp::ast {

template<class Visitor> struct Walk {
    Visitor &visit; // visit.expr(const Expr &), visit.decl(const VarDecl &)

    void expr(const Expr &e)
    {
        visit.expr(e);
        for (const Expr &o : e.operands)
            expr(o);
        for (const CallArg &a : e.callArgs)
            expr(a.value);
    }
    void type(const TypeSpec &t)
    {
        for (const TypeSpec &element : t.element)
            type(element);
        for (const VarDecl &m : t.members)
            decl(m);
    }
    void decl(const VarDecl &v)
    {
        visit.decl(v);
        type(v.type);
    }
    void sections(const std::vector<VarSection> &list)
    {
        for (const VarSection &s : list) {
            for (const VarDecl &v : s.vars)
                decl(v);
        }
    }
    void statements(const std::vector<Stmt> &list)
    {
        for (const Stmt &s : list) {
            expr(s.target);
            expr(s.value);
            if (s.to)
                expr(*s.to);
            if (s.by)
                expr(*s.by);
            for (const ConditionalBlock &b : s.branches) {
                expr(b.condition);
                statements(b.body);
            }
            for (const CaseBranch &c : s.cases)
                statements(c.body);
            statements(s.body);
        }
    }
    void body(const Body &b)
    {
        statements(b.statements);
        for (const IlInstruction &ins : b.il) {
            Expr op; // an IL operator may name a function (LD x / LIMIT 1, 5)
            op.kind = ExprKind::Call;
            op.text = ins.op;
            visit.expr(op);
            if (ins.operand)
                expr(*ins.operand);
            for (const CallArg &a : ins.callArgs)
                expr(a.value);
        }
    }
    void unit(const CompilationUnit &u)
    {
        sections(u.globals);
        for (const TypeDecl &t : u.types)
            type(t.type);
        for (const Pou &p : u.pous) {
            sections(p.sections);
            body(p.body);
            for (const SfcAction &a : p.actions)
                body(a.body);
        }
        for (const ConfigurationDecl &c : u.configurations) {
            sections(c.globals);
            for (const ResourceDecl &r : c.resources)
                sections(r.globals);
        }
    }
};

template<class Visitor> void walk(const CompilationUnit &unit, Visitor &visitor)
{
    Walk<Visitor> {visitor}.unit(unit);
}

} // namespace iec::interp::ast
